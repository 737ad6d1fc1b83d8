// keys_at: the `--keys-at N:TEXT` option of the harnesses (gpusim cosim, socsim): TEXT is typed into
// the firmware's UART when the GPU takes DOORBELL write N (counted from 1), or with `fF:TEXT` when
// it takes the doorbell that starts frame F (counted from 0): the first doorbell after F doorbells
// that asked for a swap (CTRL SWAP), so that a script can address a frame without knowing how many
// batches each frame before it took on that GPU. One parser and one schedule for both harnesses (the
// host build, bsp/host, has its own in C).
#ifndef KEYS_AT_H
#define KEYS_AT_H

#include <cctype>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

struct KeyAt {
    uint32_t at;       // the doorbell (from 1) or, with frame, the frame (from 0)
    bool frame;        // at is a frame: the doorbell that starts it
    std::string text;
};
using KeysAt = std::vector<KeyAt>;

// Appends spec's ([f]N, TEXT) to *out; on a malformed spec prints "<prog>: --keys-at wants N:TEXT
// or fF:TEXT" and returns false.
inline bool parse_keys_at(const char *prog, const std::string &spec, KeysAt *out)
{
    const bool frame = !spec.empty() && spec[0] == 'f';
    const size_t start = frame ? 1 : 0;
    const size_t colon = spec.find(':');
    bool digits = colon != std::string::npos && colon > start;
    for (size_t i = start; digits && i < colon; i++) {
        digits = std::isdigit(static_cast<unsigned char>(spec[i])) != 0;
    }
    const unsigned long at = digits ? std::strtoul(spec.c_str() + start, nullptr, 10) : 0;
    if (!digits || (!frame && at == 0) || at > UINT32_MAX) {
        std::fprintf(stderr, "%s: --keys-at wants N:TEXT (N from 1) or fF:TEXT, got '%s'\n", prog, spec.c_str());
        return false;
    }
    out->push_back(KeyAt{static_cast<uint32_t>(at), frame, spec.substr(colon + 1)});
    return true;
}

// The keys due at each doorbell: doorbell() once per DOORBELL write, in order, with whether that
// batch asks for a swap; it calls send(text) for each key of that doorbell, in the order given.
class KeysSchedule {
public:
    explicit KeysSchedule(const KeysAt &keys) : keys_(keys) {}

    template <typename Send>
    void doorbell(bool swaps, Send send)
    {
        doorbells_++;
        for (const KeyAt &k : keys_) {
            if (k.frame ? frame_starts_ && k.at == swaps_ : k.at == doorbells_) {
                send(k.text);
            }
        }
        frame_starts_ = swaps;  // the next doorbell starts a frame
        swaps_ += swaps ? 1u : 0u;
    }

private:
    const KeysAt &keys_;
    uint32_t doorbells_ = 0;
    uint32_t swaps_ = 0;
    bool frame_starts_ = true;  // doorbell 1 starts frame 0
};

#endif
