// proj_unit_tb: soc_proj_unit (the SoC's projection unit) against the firmware's own fixed-point
// projection (tests/rtl/proj_unit_ref.c: proj_setup_init, proj_unit_regs, xf_apply, proj_point),
// word for word: random set-ups (focal lengths, frame sizes up to the largest, far distances, the
// depth buffer on and off), random transforms, and vertices inside the frustum, beyond its sides,
// beyond the guard band, behind the near plane, on it, beyond far, at every normalisation shift;
// both modes (inside only where the view z allows it, as the firmware does); the seed table entry
// by entry against the firmware's. The handshake: answers held while the core is not ready, one
// answer a command, none early; the next vertex's XY taken while one is in progress, a SET or a
// second vertex's Z held until it is done; the projection's latency; an unknown function answers
// 0 and changes nothing.
//     proj_unit_tb [VERTEX_COUNT]     (built by tests/rtl/proj_unit.sh)
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <algorithm>
#include <random>

#include "Vsoc_proj_unit.h"
#include "Vsoc_proj_unit___024root.h"
#include "verilated.h"

#include "proj_unit_ref.h"
#include "gpu_regs.h"
#include "soc_map.h"

extern "C" const uint16_t fx_recip_seed[1024];  // the firmware's table (math/fixed.c)

static Vsoc_proj_unit *dut;
static std::mt19937_64 rng(27);
static uint64_t failures = 0, vertices = 0, near_cuts = 0, insides = 0, outcode_bits = 0;
static int z_latency = -1;
static unsigned shifts_seen = 0;  // bit s: a view z with s leading zeros was projected

static void tick()
{
    dut->clk = 0;
    dut->eval();
    dut->clk = 1;
    dut->eval();
}

static void fail(const char *what)
{
    std::printf("proj_unit_tb: %s\n", what);
    std::exit(1);
}

// One command: wait for cmd_ready, hand it over, wait for the one answer (the core's side holds
// rsp_ready low for a random number of clocks first, as a stalled memory stage would).
static uint32_t command(unsigned funct7, unsigned funct3, uint32_t a, uint32_t b, int *clocks = nullptr,
                        bool stall = true)
{
    int waited = 0;
    while (!dut->cmd_ready) {
        if (dut->rsp_valid) fail("an answer with no command");
        tick();
        if (++waited > 100) fail("cmd_ready stays low");
    }
    dut->cmd_valid = 1;
    dut->cmd_function_id = (funct7 << 3) | funct3;
    dut->cmd_in0 = a;
    dut->cmd_in1 = b;
    dut->rsp_ready = 0;
    tick();
    dut->cmd_valid = 0;
    dut->cmd_in0 = uint32_t(rng());  // the core's operands move on
    dut->cmd_in1 = uint32_t(rng());
    int n = 1;
    while (!dut->rsp_valid) {
        if (dut->cmd_ready) fail("cmd_ready high while a command is unanswered");
        tick();
        if (++n > 100) fail("no answer");
    }
    if (clocks) *clocks = n;
    for (int hold = stall ? int(rng() % 4) : 0; hold > 0; hold--) {  // a stalled core: the answer must stay
        const uint32_t out = dut->rsp_out;
        tick();
        if (!dut->rsp_valid || dut->rsp_out != out) fail("the answer changed before rsp_ready");
    }
    const uint32_t answer = dut->rsp_out;
    dut->rsp_ready = 1;
    tick();
    if (dut->rsp_valid) fail("a second answer to one command");
    return answer;
}

static int32_t uniform(int64_t lo, int64_t hi)  // [lo, hi]
{
    return int32_t(lo + int64_t(rng() % uint64_t(hi - lo + 1)));
}

struct setup {
    int32_t focal_px, far_q16;
    uint32_t width, height;
    int zbuf;
    int32_t m[9], t[3];
};

static void load(const setup &s)
{
    uint32_t regs[PROJ_REF_REGS];
    proj_ref_regs(s.focal_px, s.far_q16, s.width, s.height, s.zbuf, s.m, s.t, regs);
    for (uint32_t i = 0; i < PROJ_REF_REGS; i++) {
        if (command(0, SOC_PU_OP_SET, regs[i], i) != 0) fail("SET answers not 0");
    }
}

static void check_vertex(const setup &s, const int32_t v[3], int inside)
{
    uint32_t want[3];
    proj_ref_point(s.focal_px, s.far_q16, s.width, s.height, s.zbuf, s.m, s.t, v, inside, want);
    const int order = int(rng() % 4);
    if (order == 3) {  // another vertex first, then this one's Z given while that one is in progress
        const int32_t other[3] = {uniform(-(1 << 20), 1 << 20), uniform(-(1 << 20), 1 << 20), uniform(1 << 16, 1 << 22)};
        command(0, SOC_PU_OP_XY, uint32_t(other[0]), uint32_t(other[1]));
        command(0, SOC_PU_OP_Z, uint32_t(other[2]), 0);
    }
    if (command(0, SOC_PU_OP_XY, uint32_t(v[0]), uint32_t(v[1])) != 0) fail("XY answers not 0");
    int z_clocks;  // order 0: SXY right after Z, Z's answer taken at once: the whole projection
    if (command(0, SOC_PU_OP_Z, uint32_t(v[2]), uint32_t(inside), &z_clocks, order != 0) != 0)
        fail("Z answers not 0");
    if (order == 1) {  // the next vertex's XY while this one is in progress: taken, no effect on it
        if (command(0, SOC_PU_OP_XY, uint32_t(rng()), uint32_t(rng())) != 0) fail("XY answers not 0");
    } else if (order == 2) {  // a SET while in progress: held until the vertex is done
        uint32_t regs[PROJ_REF_REGS];
        proj_ref_regs(s.focal_px, s.far_q16, s.width, s.height, s.zbuf, s.m, s.t, regs);
        const uint32_t r = uint32_t(rng() % PROJ_REF_REGS);
        command(0, SOC_PU_OP_SET, regs[r] ^ 0x5A5A5A5Au, r);   // a wrong value ...
        command(0, SOC_PU_OP_SET, regs[r], r);                 // ... and the right one again
    }
    int clocks;
    const uint32_t sxy = command(0, SOC_PU_OP_SXY, 0, 0, &clocks);
    const uint32_t zd = command(0, SOC_PU_OP_ZD, 0, 0);
    const uint32_t code = command(0, SOC_PU_OP_CODE, 0, 0);
    vertices++;
    const uint32_t vz = proj_ref_view_z(s.m, s.t, v);
    if (want[2] & SOC_PU_OUT_NEAR) {
        near_cuts++;
    } else {
        if (order == 0) {  // SXY right after Z: it waits for the rest of the projection
            clocks += z_clocks + 1;  // from Z's command to SXY's answer
            if (z_latency < 0) z_latency = clocks;
            if (clocks != z_latency) fail("the projection's latency varies");
        }
        int lead = 0;
        while (lead < 31 && !(vz & (0x80000000u >> lead))) lead++;
        shifts_seen |= 1u << lead;
    }
    insides += inside != 0;
    outcode_bits |= want[2];
    if (sxy != want[0] || zd != want[1] || code != want[2]) {
        if (failures++ < 10) {
            std::printf("proj_unit_tb: v (%d, %d, %d) view z %d inside %d focal %d frame %ux%u zbuf %d: "
                        "unit %08x %08x %02x, firmware %08x %08x %02x\n",
                        v[0], v[1], v[2], int32_t(vz), inside, s.focal_px, s.width, s.height, s.zbuf,
                        sxy, zd, code, want[0], want[1], want[2]);
        }
    }
}

static setup random_setup()
{
    static const uint32_t frames[][2] = {{320, 240}, {640, 480}, {160, 120}, {GPU_FB_MAX_WIDTH, GPU_FB_MAX_HEIGHT}};
    setup s;
    const auto &f = frames[rng() % 4];
    s.width = f[0];
    s.height = f[1];
    s.focal_px = uniform(40, 300);  // proj_setup_init clamps to 64 .. 255
    s.far_q16 = uniform(1 << 16, 160 << 16);
    s.zbuf = int(rng() & 1);
    for (int i = 0; i < 9; i++) s.m[i] = uniform(-(1 << 30), 1 << 30);  // |m| <= 1, q2_30
    const int32_t reach = (rng() & 1) ? (8 << 16) : (200 << 16);
    for (int i = 0; i < 3; i++) s.t[i] = uniform(-reach, reach);
    return s;
}

static bool ref_code_bit(const setup &s, const int32_t v[3], uint32_t bit)
{
    uint32_t w[3];
    proj_ref_point(s.focal_px, s.far_q16, s.width, s.height, s.zbuf, s.m, s.t, v, 0, w);
    return (w[2] & bit) != 0;
}

// The view from the model unchanged (m = I, t = 0), and a vertex on one of the decisions' edges:
// the view z at the near plane or the far distance (one unit either side too), at a chosen
// normalisation shift, or an x or y where an outcode bit (a screen edge, the guard band) turns on,
// found by bisection on the firmware's answer (the vertex there and one unit before it).
static void edge_vertex(setup &s, int32_t v[3])
{
    for (int i = 0; i < 9; i++) s.m[i] = (i % 4 == 0) ? (1 << 30) : 0;
    s.t[0] = s.t[1] = s.t[2] = 0;
    load(s);
    const int kind = int(rng() % 4);
    v[0] = uniform(-(8 << 16), 8 << 16);
    v[1] = uniform(-(8 << 16), 8 << 16);
    v[2] = uniform(16384, s.far_q16 + (1 << 16));
    if (kind == 0) {
        const int32_t near_far[] = {16383, 16384, 16385, s.far_q16 - 1, s.far_q16, s.far_q16 + 1};
        v[2] = near_far[rng() % 6];
    } else if (kind == 1) {  // a view z of [2^k, 2^(k+1)), below 12288 units: model z and t.z
        const int k = uniform(14, 29);
        const int32_t z = std::min(uniform(int64_t(1) << k, (int64_t(2) << k) - 1), int32_t(12287) << 16);
        v[2] = std::min(z, int32_t(8191) << 16);
        s.t[2] = z - v[2];
        load(s);
    } else {
        static const uint32_t bits[] = {SOC_PU_OUT_LEFT, SOC_PU_OUT_RIGHT, SOC_PU_OUT_TOP,
                                        SOC_PU_OUT_BOTTOM, SOC_PU_OUT_GUARD};
        const uint32_t bit = bits[rng() % 5];
        const int axis = (bit == SOC_PU_OUT_TOP || bit == SOC_PU_OUT_BOTTOM) ? 1
                         : (bit == SOC_PU_OUT_GUARD) ? int(rng() % 2) : 0;
        // the bit is on at one end of [0, far x] or [-far x, 0] and off at 0 (the centre):
        // bisect between them
        // x right, y up (sy = cy - offset)
        const bool positive = (bit == SOC_PU_OUT_GUARD) ? bool(rng() & 1)
                              : (bit == SOC_PU_OUT_RIGHT || bit == SOC_PU_OUT_TOP);
        int64_t off = 0, on = positive ? int64_t(4000) << 16 : -(int64_t(4000) << 16);
        v[1 - axis] = 0;
        v[axis] = int32_t(on);
        if (!ref_code_bit(s, v, bit)) return;  // the bit never turns on along this line
        while ((on > off ? on - off : off - on) > 1) {
            const int64_t mid = (on + off) / 2;
            v[axis] = int32_t(mid);
            (ref_code_bit(s, v, bit) ? on : off) = mid;
        }
        v[axis] = int32_t((rng() & 1) ? on : off);
    }
}

int main(int argc, char **argv)
{
    Verilated::commandArgs(argc, argv);
    const uint64_t count = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 200000;
    dut = new Vsoc_proj_unit;
    dut->rst = 1;
    tick();
    tick();
    dut->rst = 0;
    dut->rsp_ready = 1;
    tick();

    // the unit's seed table, computed from its formula, against the firmware's literal one
    for (int i = 0; i < 1024; i++) {
        if (dut->rootp->soc_proj_unit__DOT__seed_rom[i] != fx_recip_seed[i]) {
            std::printf("proj_unit_tb: seed %d: unit %u, firmware %u\n", i,
                        unsigned(dut->rootp->soc_proj_unit__DOT__seed_rom[i]), unsigned(fx_recip_seed[i]));
            return 1;
        }
    }

    setup s = random_setup();
    load(s);
    for (uint64_t k = 0; k < count; k++) {
        if (k % 64 == 0) {
            s = random_setup();
            load(s);
        }
        if (k % 997 == 0) {  // unknown functions: answer 0, change nothing
            if (command(1 + unsigned(rng() % 127), SOC_PU_OP_SET, uint32_t(rng()), uint32_t(rng() % 19)) != 0 ||
                command(0, 6 + unsigned(rng() % 2), uint32_t(rng()), uint32_t(rng())) != 0)
                fail("an unknown function answers not 0");
        }
        int32_t v[3];
        const int32_t span = (k & 1) ? (4 << 16) : (60 << 16);
        for (int i = 0; i < 3; i++) v[i] = uniform(-span, span);
        if (k % 5 == 0) edge_vertex(s, v);
        const uint32_t vz = proj_ref_view_z(s.m, s.t, v);
        const bool may_be_inside = int32_t(vz) >= 16384;
        check_vertex(s, v, 0);
        if (may_be_inside) check_vertex(s, v, 1);
        if (k % 5 == 0) {
            s = random_setup();
            load(s);
        }
    }
    std::printf("%llu vertices (%llu near, %llu inside), every outcode bit %s, shifts seen 0x%x, "
                "SXY answers %d clocks after Z is given: %llu mismatches\n",
                (unsigned long long)vertices, (unsigned long long)near_cuts, (unsigned long long)insides,
                outcode_bits == 0x7F ? "met" : "NOT met", shifts_seen, z_latency,
                (unsigned long long)failures);
    delete dut;
    if (outcode_bits != 0x7F) return 1;
    // every s the range rule allows: view z from the near plane (2^14, s = 17) to below 8192 + 4096
    // units (< 2^30, s >= 2)
    if ((shifts_seen & 0x3FFFC) != 0x3FFFC) return 1;
    return failures ? 1 : 0;
}
