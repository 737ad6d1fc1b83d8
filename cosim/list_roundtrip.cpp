// list_roundtrip: `gpusim list-roundtrip [--generate N] [--seed S] [LIST...]` — checks that the
// primitive-list writer is the parser's inverse (prim_list.h), so that a list written by
// `gpusim cosim --dump-lists` reads back as the same primitives.
//
// For each LIST: parse -> write -> parse must give the same ops, field for field, and writing those
// again must give the same text (the written form is a fixed point). With --generate N, N lists of
// random ops (seeded by S, default 1) are checked too, starting from the ops: write -> parse must give
// them back; each list holds every op kind (clear, tri, line, ztri) with every value at the ends of
// its range as well as in between. Prints one line per list. Exit status: 0 all read back equal,
// 1 a difference (the first one is described), 2 a list that does not parse or a usage error.
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "prim_list.h"
#include "rng.h"

namespace {

// One op, every field as stored (not through the writer under test).
std::string describe(const ListOp &op)
{
    static const char *const names[] = {"clear", "tri", "line", "ztri", "gtri"};
    char text[200];
    std::snprintf(text, sizeof text, "%s v {%d %d %d %d %d %d} z {%u %u %u} colour %u",
                  op.kind >= 0 && op.kind < 5 ? names[op.kind] : "?", op.v[0], op.v[1], op.v[2], op.v[3], op.v[4],
                  op.v[5], op.z[0], op.z[1], op.z[2], op.color);
    return text;
}

// "" when a and b hold the same ops, else where they first differ.
std::string compare(const std::vector<ListOp> &a, const std::vector<ListOp> &b)
{
    if (a.size() != b.size()) {
        return std::to_string(a.size()) + " ops before, " + std::to_string(b.size()) + " after";
    }
    for (size_t i = 0; i < a.size(); i++) {
        if (a[i] != b[i]) {
            std::string line = prim_list_write({a[i]});
            line.pop_back();  // its '\n'
            return "op " + std::to_string(i + 1) + " was " + describe(a[i]) + ", reads back as " + describe(b[i]) +
                   " (written as '" + line + "')";
        }
    }
    return "";
}

std::string census(const std::vector<ListOp> &ops)
{
    unsigned n[5] = {0, 0, 0, 0, 0};
    for (const ListOp &op : ops) {
        n[op.kind]++;
    }
    char text[120];
    std::snprintf(text, sizeof text, "%zu ops (clear %u, tri %u, line %u, ztri %u, gtri %u)", ops.size(),
                  n[ListOp::Clear], n[ListOp::Tri], n[ListOp::Line], n[ListOp::ZTri], n[ListOp::GTri]);
    return text;
}

// ops -> text -> ops must give ops back, and the text must be written again unchanged. Returns 0, or
// 1 with a message printed.
int check_ops(const std::string &name, const std::vector<ListOp> &ops)
{
    const std::string text = prim_list_write(ops);
    std::vector<ListOp> back;
    std::string error;
    if (!prim_list_parse(text, back, error)) {
        std::printf("list-roundtrip: %s: the written list does not parse: %s\n", name.c_str(), error.c_str());
        return 1;
    }
    std::string diff = compare(ops, back);
    if (diff.empty() && prim_list_write(back) != text) {
        diff = "the list read back is written differently";
    }
    if (!diff.empty()) {
        std::printf("list-roundtrip: %s: %s\n", name.c_str(), diff.c_str());
        return 1;
    }
    std::printf("list-roundtrip: %s: %s read back equal\n", name.c_str(), census(ops).c_str());
    return 0;
}

// A value of lo..hi: an end of the range, a neighbour of an end or of 0, or anything between.
int32_t edge_value(Rng &r, int32_t lo, int32_t hi)
{
    const int32_t special[] = {lo, lo + 1, hi - 1, hi, 0, 1, -1};
    const int32_t v = special[r.next() % 7];
    return (r.next() % 2 == 0 && v >= lo && v <= hi) ? v : r.range(lo, hi);
}

ListOp random_op(Rng &r, ListOp::Kind kind)
{
    ListOp op{};
    op.kind = kind;
    const int coords = kind == ListOp::Clear ? 0 : (kind == ListOp::Line ? 4 : 6);
    for (int i = 0; i < coords; i++) {
        op.v[i] = static_cast<int32_t>(edge_value(r, -32768, 32767));
    }
    if (kind == ListOp::ZTri || kind == ListOp::GTri) {
        for (int i = 0; i < 3; i++) {
            op.z[i] = static_cast<uint32_t>(edge_value(r, 0, 65535));
        }
    }
    op.color = static_cast<uint32_t>(edge_value(r, 0, 255));
    return op;
}

std::vector<ListOp> random_list(Rng &r)
{
    std::vector<ListOp> ops;
    // Every kind with every field at both ends of its range, then random ops of random kinds.
    for (int k = 0; k < 5; k++) {
        for (int end = 0; end < 2; end++) {
            ListOp op{};
            op.kind = static_cast<ListOp::Kind>(k);
            const int coords = k == ListOp::Clear ? 0 : (k == ListOp::Line ? 4 : 6);
            for (int i = 0; i < coords; i++) {
                op.v[i] = end ? 32767 : -32768;
            }
            if (k == ListOp::ZTri || k == ListOp::GTri) {
                op.z[0] = op.z[1] = op.z[2] = end ? 65535u : 0u;
            }
            op.color = end ? 255u : 0u;
            ops.push_back(op);
        }
    }
    const int32_t more = r.range(0, 200);
    for (int32_t i = 0; i < more; i++) {
        ops.push_back(random_op(r, static_cast<ListOp::Kind>(r.range(0, 4))));
    }
    // Shuffle, so that the kinds also follow each other in every order.
    for (size_t i = ops.size() - 1; i > 0; i--) {
        std::swap(ops[i], ops[r.below(static_cast<uint32_t>(i + 1))]);
    }
    return ops;
}

}  // namespace

int list_roundtrip_main(int argc, char **argv)
{
    long generate = 0;
    uint64_t seed = 1;
    std::vector<std::string> files;
    for (int i = 0; i < argc; i++) {
        const std::string a = argv[i];
        if (a == "--generate" && i + 1 < argc) {
            generate = std::strtol(argv[++i], nullptr, 10);
        } else if (a == "--seed" && i + 1 < argc) {
            seed = std::strtoull(argv[++i], nullptr, 0);
        } else if (!a.empty() && a[0] == '-') {
            std::fprintf(stderr, "usage: gpusim list-roundtrip [--generate N] [--seed S] [LIST...]\n");
            return 2;
        } else {
            files.push_back(a);
        }
    }
    if (files.empty() && generate <= 0) {
        std::fprintf(stderr, "usage: gpusim list-roundtrip [--generate N] [--seed S] [LIST...]\n");
        return 2;
    }
    int failed = 0;
    for (const std::string &path : files) {
        std::vector<ListOp> ops;
        std::string error;
        if (!prim_list_read(path, ops, error)) {
            std::fprintf(stderr, "list-roundtrip: %s\n", error.c_str());
            return 2;
        }
        failed += check_ops(path, ops);
    }
    Rng r{seed};
    for (long g = 0; g < generate; g++) {
        failed += check_ops("generated list " + std::to_string(g + 1) + " (seed " + std::to_string(seed) + ")",
                            random_list(r));
    }
    const size_t lists = files.size() + static_cast<size_t>(generate > 0 ? generate : 0);
    if (failed != 0) {
        std::printf("list-roundtrip: %d of %zu lists do not read back equal\n", failed, lists);
        return 1;
    }
    std::printf("list-roundtrip: %zu lists, every op read back equal\n", lists);
    return 0;
}
