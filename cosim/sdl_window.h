// sdl_window: the simulated monitor in a window (SDL2) — frames in, keystrokes out — for the
// co-simulation (`gpusim cosim --window`) and the SoC simulation (`socsim --window`).
//
// Contract: open() makes a resizable window showing VGA_W x VGA_H pixels, scaled to the window with
// the aspect kept and no smoothing (at its first size, 1:1: a screenshot is the frame itself); it
// fails with *error set when there is no display. show() presents one frame (RGB888, row-major) at
// once; with a frame-rate cap (set_max_fps, 60 by default: what a board's VGA shows, 0 = none) it
// first waits until 1/cap s have passed since the previous frame, so an animation runs at the speed
// it would on a board and not faster. The title says `<name> | frame N | F fps | <status>`: N
// counts the frames shown, F is frames shown per wall second over the last second, and status is
// what the caller last set (the firmware's instructions and the GPU's busy cycles of the last frame).
// poll() handles the window's events without blocking and returns the keys typed since the last
// call as the bytes a terminal sends for them — printable characters as themselves, the arrow keys
// as ESC [ A, B, C, D — so the firmware cannot tell the window from a terminal; *closed is set once
// the window has been closed (its close button, or the window manager). Call poll() often (every
// few tens of milliseconds), or the desktop calls the window unresponsive.
#ifndef SDL_WINDOW_H
#define SDL_WINDOW_H

#include <cstdint>
#include <deque>
#include <string>

#include "no_copy.h"

struct SDL_Window;
struct SDL_Renderer;
struct SDL_Texture;

// The window's status from one of the firmware's frame lines (firmware/app/app.c: "frame N: ... |
// fw instr I | gpu cycles C | ..."): "fw instr I | gpu busy C cycles"; "" for any other line.
std::string frame_line_status(const std::string &line);

class SdlWindow : NoCopy {
public:
    ~SdlWindow() { close(); }

    bool open(const std::string &name, std::string *error);
    void close();
    bool is_open() const { return window_ != nullptr; }

    void set_max_fps(double fps) { max_fps_ = fps; }
    void set_status(const std::string &status);
    void show(const uint8_t *rgb);
    std::string poll(bool *closed);

    uint64_t frames_shown() const { return frames_shown_; }

private:
    void update_title();

    SDL_Window *window_ = nullptr;
    SDL_Renderer *renderer_ = nullptr;
    SDL_Texture *texture_ = nullptr;
    std::string name_;
    std::string status_;
    double max_fps_ = 60.0;
    double last_shown_s_ = 0.0;
    std::deque<double> shown_at_s_;  // the times of the frames shown in the last second
    uint64_t frames_shown_ = 0;
    bool closed_ = false;
};

#endif
