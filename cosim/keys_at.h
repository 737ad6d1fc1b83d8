// keys_at: the `--keys-at N:TEXT` option of the harnesses (gpusim cosim, socsim): TEXT is typed into
// the firmware's UART when the GPU takes DOORBELL write N (counted from 1). One parser for both.
#ifndef KEYS_AT_H
#define KEYS_AT_H

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

using KeysAt = std::vector<std::pair<uint32_t, std::string>>;  // (doorbell number, text)

// Appends spec's (N, TEXT) to *out; on a malformed spec prints "<prog>: --keys-at wants N:TEXT"
// and returns false.
inline bool parse_keys_at(const char *prog, const std::string &spec, KeysAt *out)
{
    const size_t colon = spec.find(':');
    if (colon == std::string::npos || colon == 0) {
        std::fprintf(stderr, "%s: --keys-at wants N:TEXT, got '%s'\n", prog, spec.c_str());
        return false;
    }
    out->emplace_back(static_cast<uint32_t>(std::strtoul(spec.c_str(), nullptr, 10)), spec.substr(colon + 1));
    return true;
}

#endif
