// sdl_window: see sdl_window.h.
#include "sdl_window.h"

#include <cstdio>
#include <cstring>
#include <ctime>

#include <SDL.h>

extern "C" {
#include "vga_monitor.h"
}

namespace {

double now_s()
{
    timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + ts.tv_nsec * 1e-9;
}

void sleep_s(double s)
{
    if (s > 0) {
        timespec ts = {static_cast<time_t>(s), static_cast<long>((s - static_cast<time_t>(s)) * 1e9)};
        nanosleep(&ts, nullptr);
    }
}

}  // namespace

std::string frame_line_status(const std::string &line)
{
    unsigned long instr = 0, gpu_cycles = 0;
    const char *at = std::strstr(line.c_str(), "| fw instr ");
    if (line.rfind("frame ", 0) != 0 || at == nullptr ||
        std::sscanf(at, "| fw instr %lu | gpu cycles %lu", &instr, &gpu_cycles) != 2) {
        return "";
    }
    char status[96];
    std::snprintf(status, sizeof status, "fw instr %lu | gpu busy %lu cycles", instr, gpu_cycles);
    return status;
}

bool SdlWindow::open(const std::string &name, std::string *error)
{
    if (SDL_InitSubSystem(SDL_INIT_VIDEO) != 0) {
        *error = std::string("no display for a window: ") + SDL_GetError();
        return false;
    }
    name_ = name;
    // Nearest-neighbour scaling: a pixel of the monitor stays a block of equal pixels.
    SDL_SetHint(SDL_HINT_RENDER_SCALE_QUALITY, "0");
    window_ = SDL_CreateWindow(name.c_str(), SDL_WINDOWPOS_UNDEFINED, SDL_WINDOWPOS_UNDEFINED, VGA_W, VGA_H,
                               SDL_WINDOW_RESIZABLE);
    if (window_ != nullptr) {
        renderer_ = SDL_CreateRenderer(window_, -1, 0);
    }
    if (renderer_ != nullptr && SDL_RenderSetLogicalSize(renderer_, VGA_W, VGA_H) == 0) {
        texture_ = SDL_CreateTexture(renderer_, SDL_PIXELFORMAT_RGB24, SDL_TEXTUREACCESS_STREAMING, VGA_W, VGA_H);
    }
    if (texture_ == nullptr) {
        *error = std::string("cannot open a window: ") + SDL_GetError();
        close();
        return false;
    }
    SDL_StartTextInput();
    SDL_SetRenderDrawColor(renderer_, 0, 0, 0, 255);
    SDL_RenderClear(renderer_);
    SDL_RenderPresent(renderer_);
    update_title();
    return true;
}

void SdlWindow::close()
{
    if (texture_ != nullptr) {
        SDL_DestroyTexture(texture_);
        texture_ = nullptr;
    }
    if (renderer_ != nullptr) {
        SDL_DestroyRenderer(renderer_);
        renderer_ = nullptr;
    }
    if (window_ != nullptr) {
        SDL_DestroyWindow(window_);
        window_ = nullptr;
        SDL_QuitSubSystem(SDL_INIT_VIDEO);
    }
}

void SdlWindow::set_status(const std::string &status)
{
    status_ = status;
    update_title();
}

void SdlWindow::update_title()
{
    if (window_ == nullptr) {
        return;
    }
    char title[512];
    std::snprintf(title, sizeof title, "%s | frame %llu | %.1f fps%s%s", name_.c_str(),
                  static_cast<unsigned long long>(frames_shown_), static_cast<double>(shown_at_s_.size()),
                  status_.empty() ? "" : " | ", status_.c_str());
    SDL_SetWindowTitle(window_, title);
}

void SdlWindow::show(const uint8_t *rgb)
{
    if (texture_ == nullptr) {
        return;
    }
    if (max_fps_ > 0) {
        sleep_s(last_shown_s_ + 1.0 / max_fps_ - now_s());
    }
    SDL_UpdateTexture(texture_, nullptr, rgb, VGA_W * 3);
    SDL_RenderClear(renderer_);
    SDL_RenderCopy(renderer_, texture_, nullptr, nullptr);
    SDL_RenderPresent(renderer_);
    const double t = now_s();
    last_shown_s_ = t;
    frames_shown_++;
    shown_at_s_.push_back(t);
    while (!shown_at_s_.empty() && shown_at_s_.front() <= t - 1.0) {
        shown_at_s_.pop_front();
    }
    update_title();
}

std::string SdlWindow::poll(bool *closed)
{
    std::string keys;
    SDL_Event e;
    while (window_ != nullptr && SDL_PollEvent(&e)) {
        if (e.type == SDL_QUIT || (e.type == SDL_WINDOWEVENT && e.window.event == SDL_WINDOWEVENT_CLOSE)) {
            closed_ = true;
        } else if (e.type == SDL_TEXTINPUT) {
            keys += e.text.text;  // UTF-8; the firmware ignores bytes it has no key for
        } else if (e.type == SDL_KEYDOWN) {
            switch (e.key.keysym.sym) {
            case SDLK_UP: keys += "\x1b[A"; break;
            case SDLK_DOWN: keys += "\x1b[B"; break;
            case SDLK_RIGHT: keys += "\x1b[C"; break;
            case SDLK_LEFT: keys += "\x1b[D"; break;
            default: break;
            }
        } else if (e.type == SDL_WINDOWEVENT && e.window.event == SDL_WINDOWEVENT_EXPOSED && texture_ != nullptr) {
            SDL_RenderClear(renderer_);  // shown again after being covered: the last frame
            SDL_RenderCopy(renderer_, texture_, nullptr, nullptr);
            SDL_RenderPresent(renderer_);
        }
    }
    *closed = closed_;
    return keys;
}
