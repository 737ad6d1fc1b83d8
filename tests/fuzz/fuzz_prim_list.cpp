// fuzz_prim_list — libFuzzer target for the primitive-list parser of `gpusim raster`
// (cosim/prim_list.h): arbitrary bytes as the list's text.
//
// Properties checked on every input (a violation aborts, which libFuzzer reports as a crash):
//   - no crash, no undefined behaviour, no leak (built with ASan + UBSan + LeakSanitizer);
//   - a rejection is one printable-ASCII message "LINE: what is wrong", LINE the 1-based number of a line that
//     exists; that line alone is rejected too, and the lines before it are accepted — so the
//     number names the line that is actually wrong;
//   - a rejection leaves the caller's ops untouched (all or nothing);
//   - an acceptance means every non-blank line (comments stripped) is a keyword and the right count
//     of plain decimal integers, each in its documented range — checked here by an independent,
//     much simpler reading of the format in prim_list.h — and the ops read back exactly;
//   - an accepted list round-trips: prim_list_write of its ops parses again, to the same ops, and
//     writing those gives the same text;
//   - prim_list_batches keeps every batch within the capacities it is given, every index inside
//     its batch's vertices, and every primitive once, in order; a clear starts a batch, and
//     clears with no primitive between them share one, cleared by the last.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "prim_list.h"

extern "C" {
#include "gpu_regs.h"
}

#define REQUIRE(cond, ...)                                                                   \
    do {                                                                                     \
        if (!(cond)) {                                                                       \
            std::fprintf(stderr, "fuzz_prim_list: %s:%d: %s: ", __FILE__, __LINE__, #cond); \
            std::fprintf(stderr, __VA_ARGS__);                                               \
            std::fprintf(stderr, "\n");                                                      \
            std::abort();                                                                    \
        }                                                                                    \
    } while (0)

namespace {

// The lines of text as std::getline splits them ('\n' only; no empty last line after a final '\n').
std::vector<std::string> split_lines(const std::string &text)
{
    std::vector<std::string> lines;
    size_t start = 0;
    while (start < text.size()) {
        size_t nl = text.find('\n', start);
        if (nl == std::string::npos) {
            nl = text.size();
        }
        lines.push_back(text.substr(start, nl - start));
        start = nl + 1;
    }
    return lines;
}

bool is_space(char c)
{
    return c == ' ' || c == '\t' || c == '\n' || c == '\v' || c == '\f' || c == '\r';
}

// An independent reading of one line, far simpler than the parser: true if the line (comment
// stripped) is blank, or one keyword and the right number of optionally signed decimal integers,
// each within its range. Fills *op for a primitive line, *blank otherwise.
bool reference_line(std::string line, bool *blank, ListOp *op)
{
    const size_t hash = line.find('#');
    if (hash != std::string::npos) {
        line.resize(hash);
    }
    std::vector<std::string> words;
    std::string word;
    for (char c : line) {
        if (is_space(c)) {
            if (!word.empty()) {
                words.push_back(word);
            }
            word.clear();
        } else {
            word += c;
        }
    }
    if (!word.empty()) {
        words.push_back(word);
    }
    *blank = words.empty();
    if (*blank) {
        return true;
    }
    size_t count;
    ListOp o{};
    if (words[0] == "clear") {
        o.kind = ListOp::Clear, count = 1;
    } else if (words[0] == "tri") {
        o.kind = ListOp::Tri, count = 7;
    } else if (words[0] == "line") {
        o.kind = ListOp::Line, count = 5;
    } else if (words[0] == "ztri") {
        o.kind = ListOp::ZTri, count = 10;
    } else if (words[0] == "gtri") {
        o.kind = ListOp::GTri, count = 10;
    } else {
        return false;
    }
    if (words.size() != count + 1) {
        return false;
    }
    std::vector<long long> v;
    for (size_t i = 1; i < words.size(); i++) {
        const std::string &w = words[i];
        size_t k = (w[0] == '+' || w[0] == '-') ? 1 : 0;
        if (k == w.size()) {
            return false;
        }
        long long value = 0;
        for (; k < w.size(); k++) {
            if (w[k] < '0' || w[k] > '9') {
                return false;
            }
            value = value * 10 + (w[k] - '0');
            if (value > 1000000) {
                return false;  // far outside every range; stops overflow
            }
        }
        v.push_back(w[0] == '-' ? -value : value);
    }
    std::vector<long long> xy;
    if (o.kind == ListOp::ZTri || o.kind == ListOp::GTri) {
        for (int i = 0; i < 3; i++) {
            if (v[3 * i + 2] < 0 || v[3 * i + 2] > 65535) {
                return false;
            }
            o.z[i] = static_cast<uint32_t>(v[3 * i + 2]);
            xy.push_back(v[3 * i]);
            xy.push_back(v[3 * i + 1]);
        }
    } else {
        xy.assign(v.begin(), v.end() - 1);
    }
    for (size_t i = 0; i < xy.size(); i++) {
        if (xy[i] < -32768 || xy[i] > 32767) {
            return false;
        }
        o.v[i] = static_cast<int32_t>(xy[i]);
    }
    if (v.back() < 0 || v.back() > 255) {
        return false;
    }
    o.color = static_cast<uint32_t>(v.back());
    *op = o;
    return true;
}

void check_batches(const std::vector<ListOp> &ops, uint32_t vtx_cap, uint32_t tri_cap)
{
    const std::vector<Batch> batches = prim_list_batches(ops, vtx_cap, tri_cap);
    size_t next = 0;  // the op the batches must hold next
    for (const Batch &b : batches) {
        REQUIRE(b.vtx.size() % 2 == 0 && b.idx.size() % 2 == 0, "odd word count");
        const size_t nv = b.vtx.size() / 2;
        const size_t np = b.idx.size() / 2;
        REQUIRE(nv <= vtx_cap && np <= tri_cap, "batch of %zu vertices, %zu prims over %u/%u", nv,
                np, vtx_cap, tri_cap);
        if (b.clear) {
            // Clears with no primitive between them make one batch, cleared by the last of them.
            REQUIRE(next < ops.size() && ops[next].kind == ListOp::Clear, "clear batch out of order");
            while (next + 1 < ops.size() && ops[next + 1].kind == ListOp::Clear) {
                next++;
            }
            REQUIRE(ops[next].color == b.clear_color, "clear batch with another clear's colour");
            next++;
        }
        for (size_t p = 0; p < np; p++) {
            REQUIRE(next < ops.size(), "more primitives than ops");
            REQUIRE(ops[next].kind != ListOp::Clear, "a clear inside a batch, not starting one");
            const ListOp &op = ops[next++];
            const uint32_t w0 = b.idx[2 * p];
            const uint32_t w1 = b.idx[2 * p + 1];
            const uint32_t i0 = (w0 >> GPU_PRIM_I0_LSB) & GPU_PRIM_I0_MASK;
            const uint32_t i1 = (w0 >> GPU_PRIM_I1_LSB) & GPU_PRIM_I1_MASK;
            const uint32_t i2 = (w1 >> GPU_PRIM_I2_LSB) & GPU_PRIM_I2_MASK;
            const uint32_t kind = (w1 >> GPU_PRIM_KIND_LSB) & GPU_PRIM_KIND_MASK;
            const bool tri = op.kind != ListOp::Line;
            REQUIRE(i0 < nv && i1 < nv && (!tri || i2 < nv), "index outside the batch");
            REQUIRE(kind == (op.kind == ListOp::GTri ? GPU_PRIM_KIND_TRI_GOURAUD
                             : tri ? GPU_PRIM_KIND_TRI : GPU_PRIM_KIND_LINE), "wrong kind");
            REQUIRE(((w1 >> GPU_PRIM_COLOR_LSB) & GPU_PRIM_COLOR_MASK) == op.color, "wrong colour");
            const uint32_t at[3] = {i0, i1, i2};
            for (int k = 0; k < (tri ? 3 : 2); k++) {
                const uint32_t xy = b.vtx[2 * at[k]];
                REQUIRE(static_cast<int16_t>(xy & 0xFFFFu) == op.v[2 * k] &&
                            static_cast<int16_t>(xy >> 16) == op.v[2 * k + 1],
                        "vertex moved");
                const uint32_t z = op.kind == ListOp::ZTri ? op.z[k] : 0;
                const uint32_t in = op.kind == ListOp::GTri ? op.z[k] : 0;
                REQUIRE(((b.vtx[2 * at[k] + 1] >> GPU_VTX_Z_LSB) & GPU_VTX_Z_MASK) == z, "depth");
                REQUIRE(((b.vtx[2 * at[k] + 1] >> GPU_VTX_I_LSB) & GPU_VTX_I_MASK) == in, "intensity");
            }
        }
    }
    REQUIRE(next == ops.size(), "%zu of %zu ops in batches", next, ops.size());
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const std::string text(reinterpret_cast<const char *>(data), size);
    const std::vector<std::string> lines = split_lines(text);

    // The caller's vector may already hold ops: a rejection must leave them as they were.
    const ListOp sentinel{ListOp::Line, {1, 2, 3, 4, 0, 0}, {0, 0, 0}, 7};
    std::vector<ListOp> ops{sentinel};
    std::string error;
    const bool ok = prim_list_parse(text, ops, error);

    if (!ok) {
        REQUIRE(ops.size() == 1 && ops[0] == sentinel, "a rejected list changed ops");
        size_t digits = 0;
        while (digits < error.size() && error[digits] >= '0' && error[digits] <= '9') {
            digits++;
        }
        REQUIRE(digits > 0 && digits <= 9 && error[0] != '0' && error.size() > digits + 2 &&
                    error[digits] == ':' && error[digits + 1] == ' ',
                "error is not 'LINE: message': '%s'", error.c_str());
        for (const char c : error) {
            REQUIRE(c >= 0x20 && c < 0x7F, "error message has byte 0x%02x", c & 0xFF);
        }
        const size_t line_no = std::strtoul(error.substr(0, digits).c_str(), nullptr, 10);
        REQUIRE(line_no >= 1 && line_no <= lines.size(), "line %zu of %zu", line_no, lines.size());
        bool blank;
        ListOp op;
        REQUIRE(!reference_line(lines[line_no - 1], &blank, &op),
                "line %zu is valid but was rejected: '%s'", line_no, error.c_str());
        for (size_t i = 0; i + 1 < line_no; i++) {
            REQUIRE(reference_line(lines[i], &blank, &op),
                    "line %zu is invalid, yet the error names line %zu", i + 1, line_no);
        }
        // The line alone gives the same message, numbered 1.
        std::vector<ListOp> alone;
        std::string error_alone;
        REQUIRE(!prim_list_parse(lines[line_no - 1], alone, error_alone), "line alone accepted");
        REQUIRE(error_alone == "1" + error.substr(digits), "'%s' vs '%s'", error_alone.c_str(),
                error.c_str());
        return 0;
    }

    REQUIRE(error.empty(), "accepted with an error message '%s'", error.c_str());
    REQUIRE(!ops.empty() && ops[0] == sentinel, "the caller's ops were changed");
    ops.erase(ops.begin());
    size_t next = 0;
    for (size_t i = 0; i < lines.size(); i++) {
        bool blank = true;
        ListOp op{};
        REQUIRE(reference_line(lines[i], &blank, &op), "invalid line %zu accepted", i + 1);
        if (!blank) {
            REQUIRE(next < ops.size() && ops[next] == op, "line %zu read wrongly", i + 1);
            next++;
        }
    }
    REQUIRE(next == ops.size(), "%zu ops from %zu lines", ops.size(), next);

    // Round trip through the writer.
    const std::string written = prim_list_write(ops);
    std::vector<ListOp> again;
    std::string error_again;
    REQUIRE(prim_list_parse(written, again, error_again), "the written list is rejected: '%s'",
            error_again.c_str());
    REQUIRE(again.size() == ops.size(), "%zu ops written, %zu read back", ops.size(), again.size());
    for (size_t i = 0; i < ops.size(); i++) {
        const ListOp &a = ops[i], &b = again[i];
        REQUIRE(b == a,
                "op %zu (kind %d, v %d %d %d %d %d %d, z %u %u %u, colour %u) is written as '%s' and reads "
                "back as kind %d, v %d %d %d %d %d %d, z %u %u %u, colour %u",
                i + 1, a.kind, a.v[0], a.v[1], a.v[2], a.v[3], a.v[4], a.v[5], a.z[0], a.z[1], a.z[2], a.color,
                prim_list_write({a}).c_str(), b.kind, b.v[0], b.v[1], b.v[2], b.v[3], b.v[4], b.v[5], b.z[0],
                b.z[1], b.z[2], b.color);
    }
    REQUIRE(prim_list_write(again) == written, "the list read back is written differently");

    check_batches(ops, GPU_VTX_CAP, GPU_TRI_CAP);
    if (!ops.empty()) {
        // Small capacities too, derived from the input so the fuzzer explores them (>= 3 and 1:
        // the smallest that hold a triangle).
        check_batches(ops, 3u + data[0] % 8u, 1u + data[size - 1] % 4u);
    }
    return 0;
}
