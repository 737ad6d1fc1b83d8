// prim_list: see prim_list.h.
#include "prim_list.h"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

extern "C" {
#include "gpu_regs.h"
}

// A word of the input as an error message quotes it: bytes outside printable ASCII as \xNN, so a
// NUL or a control byte in a bad list cannot cut or garble the message.
static std::string printable(const std::string &word)
{
    static const char hex[] = "0123456789abcdef";
    std::string out;
    for (const char c : word) {
        const unsigned char u = static_cast<unsigned char>(c);
        if (u >= 0x20 && u < 0x7F) {
            out += c;
        } else {
            out += "\\x";
            out += hex[u >> 4];
            out += hex[u & 0xF];
        }
    }
    return out;
}

bool prim_list_parse(const std::string &text, std::vector<ListOp> &ops_out, std::string &error)
{
    std::vector<ListOp> ops;  // appended to ops_out only if the whole list is valid
    std::istringstream in(text);
    std::string line;
    int number = 0;
    while (std::getline(in, line)) {
        number++;
        const size_t hash = line.find('#');
        if (hash != std::string::npos) {
            line.resize(hash);
        }
        std::istringstream words(line);
        std::string word;
        if (!(words >> word)) {
            continue;
        }
        ListOp op{};
        int count;
        if (word == "clear") {
            op.kind = ListOp::Clear;
            count = 0;
        } else if (word == "tri") {
            op.kind = ListOp::Tri;
            count = 6;
        } else if (word == "line") {
            op.kind = ListOp::Line;
            count = 4;
        } else if (word == "ztri") {
            op.kind = ListOp::ZTri;
            count = 9;
        } else if (word == "gtri") {
            op.kind = ListOp::GTri;
            count = 9;
        } else {
            error = std::to_string(number) + ": unknown primitive '" + printable(word) + "' (clear, tri, line, ztri, gtri)";
            return false;
        }
        std::vector<long> values;
        std::string token;
        while (words >> token) {
            char *end = nullptr;
            errno = 0;
            const long value = std::strtol(token.c_str(), &end, 10);
            // The whole token must be the number: `end` at the token's last byte, not merely at a
            // NUL byte inside it ("5\0x" is not 5).
            if (end != token.c_str() + token.size() || errno != 0) {
                error = std::to_string(number) + ": '" + printable(token) + "' is not an integer";
                return false;
            }
            values.push_back(value);
        }
        if (values.size() != static_cast<size_t>(count + 1)) {
            error = std::to_string(number) + ": " + word + " takes " + std::to_string(count + 1) + " integers, got " +
                    std::to_string(values.size());
            return false;
        }
        if (op.kind == ListOp::ZTri || op.kind == ListOp::GTri) {  // x y z (or i) triples: move z aside
            for (int i = 0; i < 3; i++) {
                if (values[3 * i + 2] < 0 || values[3 * i + 2] > 65535) {
                    error = std::to_string(number) + (op.kind == ListOp::ZTri ? ": depth " : ": intensity ") +
                            std::to_string(values[3 * i + 2]) +
                            " is outside 0..65535";
                    return false;
                }
                op.z[i] = static_cast<uint32_t>(values[3 * i + 2]);
            }
            values = {values[0], values[1], values[3], values[4], values[6], values[7], values[9]};
            count = 6;
        }
        for (int i = 0; i < count; i++) {
            if (values[i] < -32768 || values[i] > 32767) {
                error = std::to_string(number) + ": coordinate " + std::to_string(values[i]) +
                        " is outside Q12.4 (-32768..32767)";
                return false;
            }
            op.v[i] = static_cast<int32_t>(values[i]);
        }
        if (values[count] < 0 || values[count] > 255) {
            error = std::to_string(number) + ": colour " + std::to_string(values[count]) + " is not a palette index (0..255)";
            return false;
        }
        op.color = static_cast<uint32_t>(values[count]);
        ops.push_back(op);
    }
    ops_out.insert(ops_out.end(), ops.begin(), ops.end());
    return true;
}

bool operator==(const ListOp &a, const ListOp &b)
{
    if (a.kind != b.kind || a.color != b.color) {
        return false;
    }
    for (int i = 0; i < 6; i++) {
        if (a.v[i] != b.v[i]) {
            return false;
        }
    }
    for (int i = 0; i < 3; i++) {
        if (a.z[i] != b.z[i]) {
            return false;
        }
    }
    return true;
}

bool prim_list_read(const std::string &path, std::vector<ListOp> &ops, std::string &error)
{
    std::ifstream in(path);
    if (!in) {
        error = "cannot read " + path;
        return false;
    }
    std::stringstream text;
    text << in.rdbuf();
    if (!prim_list_parse(text.str(), ops, error)) {
        error = path + ":" + error;
        return false;
    }
    return true;
}

std::string prim_list_write(const std::vector<ListOp> &ops)
{
    std::string text;
    char line[160];
    for (const ListOp &op : ops) {
        const int32_t *v = op.v;
        line[0] = '\0';
        switch (op.kind) {
        case ListOp::Clear:
            std::snprintf(line, sizeof line, "clear %u\n", op.color);
            break;
        case ListOp::Tri:
            std::snprintf(line, sizeof line, "tri %d %d %d %d %d %d %u\n", v[0], v[1], v[2], v[3], v[4], v[5],
                          op.color);
            break;
        case ListOp::Line:
            std::snprintf(line, sizeof line, "line %d %d %d %d %u\n", v[0], v[1], v[2], v[3], op.color);
            break;
        case ListOp::ZTri:
            std::snprintf(line, sizeof line, "ztri %d %d %u %d %d %u %d %d %u %u\n", v[0], v[1], op.z[0], v[2],
                          v[3], op.z[1], v[4], v[5], op.z[2], op.color);
            break;
        case ListOp::GTri:
            std::snprintf(line, sizeof line, "gtri %d %d %u %d %d %u %d %d %u %u\n", v[0], v[1], op.z[0], v[2],
                          v[3], op.z[1], v[4], v[5], op.z[2], op.color);
            break;
        }
        text += line;
    }
    return text;
}

std::vector<Batch> prim_list_batches(const std::vector<ListOp> &ops, uint32_t vtx_cap, uint32_t tri_cap)
{
    bool depth = false;
    bool dither = false;
    for (const ListOp &op : ops) {
        depth = depth || op.kind == ListOp::ZTri;
        dither = dither || op.kind == ListOp::GTri;
    }
    std::vector<Batch> batches(1);
    batches.back().depth = depth;
    batches.back().dither = dither;
    for (const ListOp &op : ops) {
        if (op.kind == ListOp::Clear) {
            // A clear while the current batch has no primitive yet (the list's start, or a clear just
            // before) becomes that batch's clear: an empty batch of its own would only cost the GPU a
            // clear more (the first batch of a depth list always clears depth).
            if (!batches.back().idx.empty()) {
                batches.emplace_back();
            }
            batches.back().depth = depth;
            batches.back().dither = dither;
            batches.back().clear = true;
            batches.back().clear_color = op.color;
            continue;
        }
        const bool tri = op.kind != ListOp::Line;
        const uint32_t nv = tri ? 3 : 2;
        Batch *b = &batches.back();
        if (b->vtx.size() / 2 + nv > vtx_cap || b->idx.size() / 2 + 1 > tri_cap) {
            batches.emplace_back();
            b = &batches.back();
            b->depth = depth;
            b->dither = dither;
        }
        const uint32_t first = static_cast<uint32_t>(b->vtx.size() / 2);
        for (uint32_t i = 0; i < nv; i++) {
            b->vtx.push_back(static_cast<uint16_t>(op.v[2 * i]) | static_cast<uint32_t>(static_cast<uint16_t>(op.v[2 * i + 1])) << 16);
            b->vtx.push_back(op.kind == ListOp::ZTri ? op.z[i] << GPU_VTX_Z_LSB
                             : op.kind == ListOp::GTri ? op.z[i] << GPU_VTX_I_LSB : 0);
        }
        const uint32_t kind = op.kind == ListOp::GTri ? GPU_PRIM_KIND_TRI_GOURAUD
                              : tri ? GPU_PRIM_KIND_TRI : GPU_PRIM_KIND_LINE;
        const uint32_t i2 = tri ? first + 2 : 0;
        b->idx.push_back(first | (first + 1) << 16);
        b->idx.push_back(i2 | op.color << GPU_PRIM_COLOR_LSB | kind << GPU_PRIM_KIND_LSB);
    }
    return batches;
}
