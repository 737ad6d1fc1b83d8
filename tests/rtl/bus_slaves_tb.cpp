// bus_slaves_tb: gpu_wb_slave and gpu_axil_slave in front of a real gpu_top (tests/rtl/bus_slaves_top.v),
// each driven by a seeded random master with random stalls, against
//   - a reference model of what the register file must read (contract values of ID … FB_SIZE, the
//     last value written to each rw register masked to its fields, 0 for unmapped and write-only
//     addresses, DONE_SEQ and the PERF_* counters of the last batch);
//   - the native bus itself (observed between slave and GPU): every accepted request makes exactly
//     one native access with its address and data, a refused one (partial write strobe) none, and
//     read data is the GPU's bus_rdata;
//   - the protocols, every clock: Wishbone answers exactly once per request, never without
//     cyc & stb, ack and err never together, ack in the clock after the request's first clock;
//     AXI4-Lite B/R valid held with stable data until ready, no response without its request,
//     responses in order, no request waiting forever (fair arbitration);
//   - a batch (vertices, a primitive, registers, DOORBELL) written through the slave, polled to
//     DONE_SEQ, its PERF counters against an exact reference rasterization of the triangle; a
//     partial-strobe write to the primitive, to VTX_COUNT and to DOORBELL must change nothing.
//     bus_slaves_tb [OPS_PER_PROTOCOL [SEED]]      (built by tests/rtl/bus_slaves.sh)
#include <algorithm>
#include <cstdarg>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <random>
#include <set>
#include <utility>

#include "Vbus_slaves_top.h"
#include "gpu_regs.h"
#include "verilated.h"

static Vbus_slaves_top *top;
static std::mt19937_64 rng;
static uint64_t cycle_no = 0;
static long failures = 0, protocol_errors = 0;

static void fail(bool protocol, const char *fmt, ...)
{
    failures++;
    if (protocol) protocol_errors++;
    if (failures > 20) return;
    va_list ap;
    va_start(ap, fmt);
    std::printf("bus_slaves_tb: cycle %llu: ", (unsigned long long)cycle_no);
    std::vprintf(fmt, ap);
    std::printf("\n");
    va_end(ap);
}

static uint32_t rnd(uint32_t n) { return uint32_t(rng() % n); }
static bool chance(double p) { return std::uniform_real_distribution<double>(0, 1)(rng) < p; }
// Stalls: mostly none, sometimes short, now and then long.
static int stall()
{
    const uint32_t r = rnd(100);
    return r < 55 ? 0 : r < 90 ? 1 + int(rnd(3)) : 4 + int(rnd(12));
}

// ---- the reference model: what each address must read back -----------------------------------------
struct Model {
    uint32_t reg[64];  // the register window, by word
    void reset()
    {
        std::fill(reg, reg + 64, 0u);
        reg[GPU_REG_ID / 4] = GPU_ID_VALUE;
        reg[GPU_REG_VERSION / 4] = GPU_VERSION_VALUE;
        reg[GPU_REG_CAPS / 4] = (GPU_DEFAULT_SPAN_W << GPU_CAPS_SPAN_W_LSB) |
                                (GPU_DEFAULT_ENABLE_LINES ? GPU_CAPS_LINES_MASK : 0) |
                                (GPU_DEFAULT_ENABLE_ZBUF ? GPU_CAPS_ZBUF_MASK : 0) |
                                (GPU_DEFAULT_ENABLE_GOURAUD ? GPU_CAPS_GOURAUD_MASK : 0) |
                                (GPU_DEFAULT_ENABLE_WMASK ? GPU_CAPS_WMASK_MASK : 0);
        reg[GPU_REG_FB_WRITE_MASK / 4] = GPU_WMASK_LO_MASK | GPU_WMASK_HI_MASK;  // all of each pixel
        reg[GPU_REG_VTX_CAP / 4] = GPU_VTX_CAP;
        reg[GPU_REG_TRI_CAP / 4] = GPU_TRI_CAP;
        reg[GPU_REG_FB_SIZE / 4] = (GPU_FB_HEIGHT << 16) | GPU_FB_WIDTH;
        reg[GPU_REG_STRIP / 4] = (GPU_FB_HEIGHT - 1u) << GPU_STRIP_LAST_LSB;  // the whole frame
    }
    static uint32_t rw_mask(uint32_t addr)  // 0 for an address that is not a rw register
    {
        switch (addr) {
        case GPU_REG_CTRL:
            return GPU_CTRL_CLEAR_MASK | GPU_CTRL_SWAP_MASK | GPU_CTRL_ZTEST_MASK | GPU_CTRL_ZCLEAR_MASK |
                   GPU_CTRL_DITHER_MASK | GPU_CTRL_WALK_MASK;
        case GPU_REG_CLEAR_COLOR: return 0xffu;
        case GPU_REG_FB_WRITE_MASK: return GPU_DEFAULT_ENABLE_WMASK ? GPU_WMASK_LO_MASK | GPU_WMASK_HI_MASK : 0u;
        case GPU_REG_VTX_BASE: case GPU_REG_VTX_COUNT: case GPU_REG_TRI_BASE: case GPU_REG_TRI_COUNT:
        case GPU_REG_STRIP: case GPU_REG_DOORBELL: case GPU_REG_RESET: return 0xffffffffu;
        default: return 0;
        }
    }
    void write(uint32_t addr, uint32_t data)
    {
        if (rw_mask(addr)) reg[addr / 4] = data & rw_mask(addr);
    }
    uint32_t read(uint32_t addr) const { return addr < GPU_WIN_REGS_BYTES ? reg[addr / 4] : 0; }
};
static Model model;

// ---- one access and its progress -----------------------------------------------------------------
struct Op {
    bool we = false;
    uint32_t addr = 0, data = 0;   // byte address (aligned), write data
    uint32_t strb = 0xf;           // write strobes (Wishbone sel; for a read a random sel)
    bool refuse = false;           // a partial write: expect err / SLVERR and no native access
    bool known = false;            // a read whose value the model knows
    uint32_t expect = 0;
    bool abort = false;            // Wishbone: the master abandons this request after one clock
    int aw_delay = 0, w_delay = 0; // AXI: clocks before the channel's valid rises
    uint64_t pushed = 0;
    // progress, filled in by the monitors
    bool aw_done = false, w_done = false, a_done = false;  // AXI handshakes (a_done: AR)
    int native = 0;
    bool native_rdata_valid = false;
    uint32_t native_rdata = 0;
    bool done = false, resp_err = false;
    uint32_t rdata = 0;
};

static const uint32_t RW_REGS[] = {GPU_REG_CTRL, GPU_REG_VTX_BASE, GPU_REG_VTX_COUNT, GPU_REG_TRI_BASE,
                                   GPU_REG_TRI_COUNT, GPU_REG_CLEAR_COLOR, GPU_REG_STRIP, GPU_REG_RESET};

static uint32_t random_data()
{
    const uint32_t r = rnd(10);
    return r == 0 ? 0u : r == 1 ? 0xffffffffu : uint32_t(rng());
}

static uint32_t random_any_addr()
{
    switch (rnd(6)) {
    case 0: case 1: case 2: return rnd(GPU_WIN_REGS_BYTES / 4) * 4;
    case 3: return GPU_WIN_PALETTE + rnd(GPU_WIN_PALETTE_BYTES / 4) * 4;
    case 4: return GPU_WIN_VTX + rnd(GPU_WIN_VTX_BYTES / 4) * 4;
    default: return rnd(GPU_APERTURE_BYTES / 4) * 4;  // anywhere, also unmapped gaps
    }
}

static Op *make_write(uint32_t addr, uint32_t data, uint32_t strb = 0xf)
{
    Op *op = new Op;
    op->we = true;
    op->addr = addr;
    op->data = data;
    op->strb = strb;
    op->refuse = strb != 0xf;
    return op;
}

static Op *make_read(uint32_t addr, bool known)
{
    Op *op = new Op;
    op->addr = addr;
    op->strb = rnd(16);  // reads ignore sel
    op->known = known;
    return op;
}

// Random traffic while no batch runs (so every register's value is known).
static Op *random_op()
{
    const uint32_t r = rnd(100);
    Op *op;
    if (r < 30) {
        op = make_write(RW_REGS[rnd(sizeof RW_REGS / sizeof RW_REGS[0])], random_data());
    } else if (r < 40) {  // partial strobes, also on DOORBELL: must neither write nor start a batch
        const uint32_t addr = rnd(4) == 0 ? GPU_REG_DOORBELL
                              : rnd(2) ? RW_REGS[rnd(sizeof RW_REGS / sizeof RW_REGS[0])] : random_any_addr();
        op = make_write(addr, random_data(), rnd(15));
    } else if (r < 47) {  // read-only registers, unmapped offsets: ignored
        uint32_t addr;
        do {
            addr = rnd(2) ? rnd(GPU_WIN_REGS_BYTES / 4) * 4 : random_any_addr();
        } while (Model::rw_mask(addr) != 0 || addr == GPU_REG_DOORBELL ||
                 (addr >= GPU_WIN_PALETTE && addr < GPU_WIN_PALETTE + GPU_WIN_PALETTE_BYTES) || addr >= GPU_WIN_VTX);
        op = make_write(addr, random_data());
    } else if (r < 55) {  // palette, vertex and index buffers
        const uint32_t w = rnd(3);
        const uint32_t addr = w == 0   ? GPU_WIN_PALETTE + rnd(GPU_WIN_PALETTE_BYTES / 4) * 4
                              : w == 1 ? GPU_WIN_VTX + rnd(GPU_WIN_VTX_BYTES / 4) * 4
                                       : GPU_WIN_IDX + rnd(GPU_WIN_IDX_BYTES / 4) * 4;
        op = make_write(addr, random_data());
    } else {
        op = make_read(rnd(10) < 7 ? rnd(GPU_WIN_REGS_BYTES / 4) * 4 : random_any_addr(), true);
    }
    op->aw_delay = stall();
    op->w_delay = stall();
    return op;
}

// ---- the protocol masters and monitors -------------------------------------------------------------
enum Proto { WB = 0, AXI = 1 };
static Proto proto;
static std::deque<Op *> queue_wb;          // Wishbone: waiting to be presented
static Op *wb_cur = nullptr;               // Wishbone: being presented (cyc & stb)
static int wb_age = 0, wb_gap = 0;
static bool wb_gap_cyc = false;
static std::deque<Op *> wq, rq;            // AXI: writes until B, reads until R, in order
static Op *aw_cur = nullptr, *w_cur = nullptr, *ar_cur = nullptr;
static std::deque<Op *> native_reads;      // native reads waiting for bus_rvalid
static bool prev_bvalid_stall = false, prev_rvalid_stall = false;
static uint32_t prev_bresp = 0, prev_rdata = 0, prev_rresp = 0;
static long completed[2] = {0, 0}, refused[2] = {0, 0};
// Coverage of the situations the slaves must handle; each must have happened, or the test says so.
static long cov_wb_back_to_back = 0, cov_wb_abort = 0, cov_wb_cyc_gap = 0, cov_w_first = 0, cov_aw_first = 0,
            cov_aw_w_same = 0, cov_b_stall = 0, cov_r_stall = 0, cov_rw_same_clock = 0;
static uint64_t batch_pixels = 0;
static int pending_w[GPU_APERTURE_BYTES / 4], pending_r[GPU_APERTURE_BYTES / 4];

static void complete(Op *op)
{
    op->done = true;
    completed[proto]++;
    if (op->refuse) refused[proto]++;
    if (op->we) pending_w[op->addr / 4]--;
    else pending_r[op->addr / 4]--;
    if (!op->we && op->known && !op->abort && op->rdata != op->expect) {
        fail(false, "read 0x%05x = 0x%08x, the model says 0x%08x", op->addr, op->rdata, op->expect);
    }
}

static bool outstanding() { return wb_cur || !queue_wb.empty() || !wq.empty() || !rq.empty(); }

// Can op be handed to the master now? AXI reads and writes overtake each other, so a read waits for
// the writes to its address and a write for the reads of it: then the model's value is exact.
static bool push(Op *op)
{
    if (proto == WB) {
        if (queue_wb.size() >= 2) return false;
    } else {
        if ((op->we ? wq.size() : rq.size()) >= 3) return false;
        if (op->we ? pending_r[op->addr / 4] : pending_w[op->addr / 4]) return false;
    }
    if (op->we) {
        pending_w[op->addr / 4]++;
        if (!op->refuse) model.write(op->addr, op->data);
    } else {
        pending_r[op->addr / 4]++;
        if (op->known) op->expect = model.read(op->addr);
    }
    op->pushed = cycle_no;
    if (proto == WB) queue_wb.push_back(op);
    else (op->we ? wq : rq).push_back(op);
    return true;
}

static void drive_inputs()
{
    top->sel = proto;
    // Wishbone (idle lines carry garbage, which the slave must ignore)
    if (proto == WB && wb_cur) {
        top->wb_cyc = 1;
        top->wb_stb = 1;
        top->wb_we = wb_cur->we;
        top->wb_adr = wb_cur->addr >> 2;
        top->wb_dat_w = wb_cur->we ? wb_cur->data : uint32_t(rng());
        top->wb_sel = wb_cur->strb;
    } else {
        top->wb_cyc = proto == WB && wb_gap_cyc;
        top->wb_stb = 0;
        top->wb_we = rnd(2);
        top->wb_adr = rnd(1u << 15);
        top->wb_dat_w = uint32_t(rng());
        top->wb_sel = rnd(16);
    }
    // AXI4-Lite: valids held until ready; address bits [1:0] random (ignored)
    top->s_axi_awvalid = aw_cur != nullptr;
    top->s_axi_awaddr = aw_cur ? (aw_cur->addr | rnd(4)) : rnd(1u << 17);
    top->s_axi_wvalid = w_cur != nullptr;
    top->s_axi_wdata = w_cur ? w_cur->data : uint32_t(rng());
    top->s_axi_wstrb = w_cur ? w_cur->strb : rnd(16);
    top->s_axi_arvalid = ar_cur != nullptr;
    top->s_axi_araddr = ar_cur ? (ar_cur->addr | rnd(4)) : rnd(1u << 17);
    top->s_axi_bready = proto == AXI && chance(0.7);
    top->s_axi_rready = proto == AXI && chance(0.7);
}

// Native bus, seen between the slave and the GPU (outputs of this clock, before the edge).
static void monitor_native()
{
    if (top->mon_rvalid) {
        if (native_reads.empty()) {
            fail(true, "bus_rvalid with no native read out");
        } else {
            Op *op = native_reads.front();
            native_reads.pop_front();
            op->native_rdata_valid = true;
            op->native_rdata = top->mon_rdata;
        }
    }
    if (!top->mon_valid) return;
    const bool we = top->mon_write;
    const uint32_t addr = uint32_t(top->mon_addr) << 2;
    Op *op = nullptr;
    if (proto == WB) {
        if (!wb_cur || wb_age != 0) {
            fail(true, "native access 0x%05x outside a Wishbone request's first clock", addr);
            return;
        }
        op = wb_cur;
    } else {
        for (Op *o : we ? wq : rq) {
            if (o->native == 0 && !o->refuse) { op = o; break; }
        }
        if (!op || !(we ? (op->aw_done && op->w_done) : op->a_done)) {
            fail(true, "native %s 0x%05x before its AXI request was accepted", we ? "write" : "read", addr);
            return;
        }
    }
    if (proto == AXI) {  // the other direction also held and waiting: the arbiter chose
        Op *w = wq.empty() ? nullptr : wq.front(), *r = rq.empty() ? nullptr : rq.front();
        const bool w_waits = w && w != op && w->aw_done && w->w_done && w->native == 0 && !top->s_axi_bvalid;
        const bool r_waits = r && r != op && r->a_done && r->native == 0;
        cov_rw_same_clock += we ? r_waits : w_waits;
    }
    op->native++;
    if (op->refuse) fail(true, "partial write 0x%05x (strobes %x) reached the GPU", op->addr, op->strb);
    if (we != op->we || addr != op->addr || (we && top->mon_wdata != op->data)) {
        fail(true, "native %s 0x%05x 0x%08x, request was %s 0x%05x 0x%08x", we ? "write" : "read", addr,
             top->mon_wdata, op->we ? "write" : "read", op->addr, op->data);
    }
    if (!we) native_reads.push_back(op);
}

// Wishbone master and checks; returns after deciding the next clock's request.
static void wishbone_clock()
{
    const bool req = top->wb_cyc && top->wb_stb;
    const bool ack = top->wb_ack, err = top->wb_err;
    if (ack && err) fail(true, "wb_ack and wb_err together");
    if ((ack || err) && !req) fail(true, "wb %s without cyc & stb", ack ? "ack" : "err");
    if (wb_cur && (ack || err)) {
        Op *op = wb_cur;
        if (wb_age != 1) fail(true, "wb answer %d clocks after the request (want 1)", wb_age);
        if (err != op->refuse) fail(true, "wb %s for %s 0x%05x strobes %x", err ? "err" : "ack",
                                    op->we ? "write" : "read", op->addr, op->strb);
        if (op->native != (op->refuse ? 0 : 1)) fail(true, "wb request 0x%05x made %d native accesses",
                                                      op->addr, op->native);
        op->resp_err = err;
        op->rdata = top->wb_dat_r;
        if (!op->we && (!op->native_rdata_valid || op->rdata != op->native_rdata)) {
            fail(true, "wb read data 0x%08x is not the GPU's answer", op->rdata);
        }
        complete(op);
        wb_cur = nullptr;
        if (!queue_wb.empty() && chance(0.4)) {  // next request straight away: stb stays high
            cov_wb_back_to_back++;
            wb_cur = queue_wb.front();
            queue_wb.pop_front();
            wb_age = 0;
        } else {
            wb_gap = 1 + stall();
            wb_gap_cyc = chance(0.5);
        }
        return;
    }
    if (wb_cur) {
        if (wb_cur->abort && wb_age == 0) {  // drop cyc (or stb) before the answer
            Op *op = wb_cur;
            wb_cur = nullptr;
            if (op->native > 1) fail(true, "abandoned request made %d native accesses", op->native);
            cov_wb_abort++;
            complete(op);
            wb_gap = 1 + stall();
            wb_gap_cyc = chance(0.5);
            return;
        }
        if (++wb_age > 50) {
            fail(true, "wb request 0x%05x never answered", wb_cur->addr);
            std::exit(1);
        }
        return;
    }
    if (wb_gap > 0) {
        cov_wb_cyc_gap += top->wb_cyc;
        wb_gap--;
        return;
    }
    if (!queue_wb.empty()) {
        wb_cur = queue_wb.front();
        queue_wb.pop_front();
        wb_age = 0;
    }
}

static Op *next_for(std::deque<Op *> &q, bool Op::*done, int Op::*delay)
{
    for (Op *o : q) {
        if (!(o->*done)) {
            if (o->*delay > 0) {
                o->*delay -= 1;
                return nullptr;
            }
            return o;
        }
    }
    return nullptr;
}

static void axi_clock()
{
    // B and R: held while not accepted, never without their request, in order.
    const bool bvalid = top->s_axi_bvalid, rvalid = top->s_axi_rvalid;
    if (prev_bvalid_stall && (!bvalid || top->s_axi_bresp != prev_bresp)) {
        fail(true, "BVALID/BRESP changed before BREADY");
    }
    if (prev_rvalid_stall && (!rvalid || top->s_axi_rdata != prev_rdata || top->s_axi_rresp != prev_rresp)) {
        fail(true, "RVALID/RDATA/RRESP changed before RREADY");
    }
    if (bvalid && (wq.empty() || !wq.front()->aw_done || !wq.front()->w_done)) {
        fail(true, "BVALID with no write accepted");
    } else if (bvalid && top->s_axi_bready) {
        Op *op = wq.front();
        wq.pop_front();
        const uint32_t want = op->refuse ? 2u : 0u;
        if (top->s_axi_bresp != want) fail(true, "BRESP %u for write 0x%05x strobes %x", top->s_axi_bresp,
                                            op->addr, op->strb);
        if (op->native != (op->refuse ? 0 : 1)) fail(true, "AXI write 0x%05x made %d native accesses",
                                                      op->addr, op->native);
        op->resp_err = top->s_axi_bresp != 0;
        complete(op);
    }
    if (rvalid && (rq.empty() || !rq.front()->a_done)) {
        fail(true, "RVALID with no read accepted");
    } else if (rvalid && top->s_axi_rready) {
        Op *op = rq.front();
        rq.pop_front();
        op->rdata = top->s_axi_rdata;
        if (top->s_axi_rresp != 0) fail(true, "RRESP %u for read 0x%05x", top->s_axi_rresp, op->addr);
        if (op->native != 1) fail(true, "AXI read 0x%05x made %d native accesses", op->addr, op->native);
        if (!op->native_rdata_valid || op->rdata != op->native_rdata) {
            fail(true, "RDATA 0x%08x is not the GPU's answer", op->rdata);
        }
        complete(op);
    }
    prev_bvalid_stall = bvalid && !top->s_axi_bready;
    cov_b_stall += prev_bvalid_stall;
    cov_r_stall += rvalid && !top->s_axi_rready;

    prev_bresp = top->s_axi_bresp;
    prev_rvalid_stall = rvalid && !top->s_axi_rready;
    prev_rdata = top->s_axi_rdata;
    prev_rresp = top->s_axi_rresp;
    // AW, W, AR handshakes; then the next valid of each channel, after its op's stall.
    const bool aw_hs = aw_cur && top->s_axi_awready, w_hs = w_cur && top->s_axi_wready;
    if (aw_hs && w_hs && aw_cur == w_cur) cov_aw_w_same++;
    else if (aw_hs && !aw_cur->w_done) cov_aw_first++;
    else if (w_hs && !w_cur->aw_done) cov_w_first++;
    if (aw_hs) { aw_cur->aw_done = true; aw_cur = nullptr; }
    if (w_hs) { w_cur->w_done = true; w_cur = nullptr; }
    if (ar_cur && top->s_axi_arready) { ar_cur->a_done = true; ar_cur = nullptr; }
    if (!aw_cur) aw_cur = next_for(wq, &Op::aw_done, &Op::aw_delay);
    if (!w_cur) w_cur = next_for(wq, &Op::w_done, &Op::w_delay);
    if (!ar_cur) ar_cur = next_for(rq, &Op::a_done, &Op::aw_delay);
    for (std::deque<Op *> *q : {&wq, &rq}) {
        if (!q->empty() && cycle_no - q->front()->pushed > 500) {
            fail(true, "AXI %s 0x%05x not answered in 500 clocks", q == &wq ? "write" : "read", q->front()->addr);
            std::exit(1);
        }
    }
}

static void tick()
{
    drive_inputs();
    top->clk = 0;
    top->eval();
    monitor_native();
    if (proto == WB) wishbone_clock();
    else axi_clock();
    if (proto != WB && (top->wb_ack || top->wb_err)) fail(true, "Wishbone answer while it is not in use");
    top->clk = 1;
    top->eval();
    cycle_no++;
}

static void reset_all()
{
    wb_cur = nullptr;
    wb_gap = 0;
    wb_gap_cyc = false;
    aw_cur = w_cur = ar_cur = nullptr;
    prev_bvalid_stall = prev_rvalid_stall = false;
    top->rst = 1;
    for (int i = 0; i < 4; i++) tick();
    top->rst = 0;
    model.reset();
}

// Run op to its answer (other traffic: none).
static Op *sync(Op *op)
{
    while (!push(op)) tick();
    while (!op->done) tick();
    return op;
}

static uint32_t read_sync(uint32_t addr)
{
    Op *op = sync(make_read(addr, false));
    const uint32_t v = op->rdata;
    delete op;
    return v;
}

static void write_sync(uint32_t addr, uint32_t data, uint32_t strb = 0xf)
{
    Op *op = make_write(addr, data, strb);
    op->aw_delay = stall();
    op->w_delay = stall();
    sync(op);
    if (op->resp_err != (strb != 0xf)) fail(false, "write 0x%05x strobes %x answered %s", addr, strb,
                                            op->resp_err ? "error" : "OK");
    delete op;
}

static void check_read(uint32_t addr, uint32_t want, const char *what)
{
    const uint32_t v = read_sync(addr);
    if (v != want) fail(false, "%s reads %u (0x%08x), want %u", what, v, v, want);
}

// ---- a batch through the slave, checked against an exact rasterization of its triangle -----------
struct V { int64_t x, y; };
static int64_t edge(V a, V b, V p) { return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x); }
static int64_t floor_div(int64_t a, int64_t b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }

struct Expect { uint32_t drawn, rejected, pixels, samples, spans; };
static Expect rasterize(V v0, V v1, V v2)
{
    Expect e = {0, 1, 0, 0, 0};
    const int64_t area = edge(v0, v1, v2);
    if (area == 0) return e;
    if (area < 0) std::swap(v1, v2);
    const int64_t minx = std::min({v0.x, v1.x, v2.x}), maxx = std::max({v0.x, v1.x, v2.x});
    const int64_t miny = std::min({v0.y, v1.y, v2.y}), maxy = std::max({v0.y, v1.y, v2.y});
    const int64_t px0 = std::max<int64_t>(0, -floor_div(-(minx - 8), 16));
    const int64_t px1 = std::min<int64_t>(GPU_FB_WIDTH - 1, floor_div(maxx - 8, 16));
    const int64_t py0 = std::max<int64_t>(0, -floor_div(-(miny - 8), 16));
    const int64_t py1 = std::min<int64_t>(GPU_FB_HEIGHT - 1, floor_div(maxy - 8, 16));
    if (px0 > px1 || py0 > py1) return e;
    e = {1, 0, 0, uint32_t((px1 - px0 + 1) * (py1 - py0 + 1)), 0};
    const V ea[3] = {v0, v1, v2}, eb[3] = {v1, v2, v0};
    std::set<std::pair<int64_t, int64_t>> spans;
    for (int64_t py = py0; py <= py1; py++) {
        for (int64_t px = px0; px <= px1; px++) {
            const V p = {16 * px + 8, 16 * py + 8};
            bool in = true;
            for (int k = 0; k < 3; k++) {
                const int64_t dx = eb[k].x - ea[k].x, dy = eb[k].y - ea[k].y;
                const int64_t ev = edge(ea[k], eb[k], p);
                const bool top_left = dy < 0 || (dy == 0 && dx > 0);
                in = in && (ev > 0 || (ev == 0 && top_left));
            }
            if (in) {
                e.pixels++;
                spans.insert({px / GPU_DEFAULT_SPAN_W, py});
            }
        }
    }
    e.spans = uint32_t(spans.size());
    return e;
}

static long batches = 0;
static void batch()
{
    V v[3];
    for (V &p : v) p = {int64_t(rnd(48 * 16)) - 64, int64_t(rnd(48 * 16)) - 64};  // a corner, some guard band
    const uint32_t vb = rnd(GPU_VTX_CAP - 3), tb = rnd(GPU_TRI_CAP - 1), color = rnd(256);
    for (int i = 0; i < 3; i++) {
        write_sync(GPU_WIN_VTX + (vb + i) * 8, (uint32_t(v[i].y & 0xffff) << 16) | uint32_t(v[i].x & 0xffff));
        write_sync(GPU_WIN_VTX + (vb + i) * 8 + 4, rnd(65536));
    }
    write_sync(GPU_WIN_IDX + tb * 8, 0u | (1u << 16));
    write_sync(GPU_WIN_IDX + tb * 8 + 4, 2u | (color << 16) | (0u << 24));
    write_sync(GPU_WIN_IDX + tb * 8, 5u | (6u << 16), rnd(15));  // would make the triangle invalid
    write_sync(GPU_REG_CTRL, 0);
    write_sync(GPU_REG_VTX_BASE, vb);
    write_sync(GPU_REG_VTX_COUNT, 3);
    write_sync(GPU_REG_VTX_COUNT, 0, rnd(15));                      // would reject it
    write_sync(GPU_REG_TRI_BASE, tb);
    write_sync(GPU_REG_TRI_COUNT, 1);
    write_sync(GPU_REG_CLEAR_COLOR, rnd(256));
    write_sync(GPU_REG_STRIP, GPU_STRIP_LAST_MASK);  // rows 0 .. the frame's last, whatever went before
    const uint32_t tag = uint32_t(rng()) | 1u;
    write_sync(GPU_REG_DOORBELL, tag);
    int polls = 0;
    while (read_sync(GPU_REG_DONE_SEQ) != tag) {
        if (++polls > 2000) {
            fail(false, "batch %ld: DONE_SEQ never reached its tag", batches);
            return;
        }
    }
    model.reg[GPU_REG_DONE_SEQ / 4] = tag;
    while (read_sync(GPU_REG_STATUS) & GPU_STATUS_BUSY_MASK) {
        if (++polls > 2000) {
            fail(false, "batch %ld: BUSY stays set", batches);
            return;
        }
    }
    const Expect e = rasterize(v[0], v[1], v[2]);
    batch_pixels += e.pixels;
    check_read(GPU_REG_ERRORS, 0, "ERRORS");
    check_read(GPU_REG_PERF_TRIS_IN, 1, "PERF_TRIS_IN");
    check_read(GPU_REG_PERF_TRIS_DRAWN, e.drawn, "PERF_TRIS_DRAWN");
    check_read(GPU_REG_PERF_TRIS_REJECTED, e.rejected, "PERF_TRIS_REJECTED");
    check_read(GPU_REG_PERF_PIXELS, e.pixels, "PERF_PIXELS");
    check_read(GPU_REG_PERF_SAMPLES, e.samples, "PERF_SAMPLES");
    check_read(GPU_REG_PERF_SPANS_WRITTEN, e.spans, "PERF_SPANS_WRITTEN");
    // What the reference does not compute, the random reads after this batch must see unchanged.
    model.reg[GPU_REG_PERF_TRIS_IN / 4] = 1;
    model.reg[GPU_REG_PERF_TRIS_DRAWN / 4] = e.drawn;
    model.reg[GPU_REG_PERF_TRIS_REJECTED / 4] = e.rejected;
    model.reg[GPU_REG_PERF_PIXELS / 4] = e.pixels;
    model.reg[GPU_REG_PERF_SAMPLES / 4] = e.samples;
    model.reg[GPU_REG_PERF_SPANS_WRITTEN / 4] = e.spans;
    model.reg[GPU_REG_PERF_BUSY_CYCLES / 4] = read_sync(GPU_REG_PERF_BUSY_CYCLES);
    model.reg[GPU_REG_PERF_SPANS_VISITED / 4] = read_sync(GPU_REG_PERF_SPANS_VISITED);
    batches++;
}

static void random_traffic(long n)
{
    Op *next = nullptr;
    std::deque<Op *> all;
    long made = 0;
    while (made < n || outstanding()) {
        if (!next && made < n && chance(0.8)) {
            next = random_op();
            // Wishbone masters may abandon a request: reads, and writes whose effect the model does
            // not need (refused, or to addresses that read back 0 or a constant).
            next->abort = proto == WB && (!next->we || next->refuse || Model::rw_mask(next->addr) == 0) &&
                          chance(0.03);
            made++;
        }
        if (next && push(next)) {
            all.push_back(next);
            next = nullptr;
        }
        tick();
        // Kept a while after their answer: an abandoned read's native answer may still come.
        while (all.size() > 16 && all.front()->done) {
            delete all.front();
            all.pop_front();
        }
    }
    for (int i = 0; i < 4; i++) tick();
    for (Op *o : all) delete o;
}

int main(int argc, char **argv)
{
    const long ops = argc > 1 ? std::atol(argv[1]) : 20000;
    const uint64_t seed = argc > 2 ? std::strtoull(argv[2], nullptr, 0) : 1;
    rng.seed(seed);
    top = new Vbus_slaves_top;
    long per_proto_batches[2] = {0, 0};
    const int rounds = 8;  // batches per protocol
    for (Proto p : {WB, AXI}) {
        proto = p;
        reset_all();
        const long before = batches;
        for (int r = 0; r < rounds; r++) {
            random_traffic(ops / rounds);
            batch();
        }
        random_traffic(ops / 10);
        per_proto_batches[p] = batches - before;
    }
    delete top;
    std::printf("bus-slaves coverage: wishbone back-to-back %ld, cyc held between %ld, abandoned %ld; axi AW first %ld, "
                "W first %ld, together %ld, B stalled %ld, R stalled %ld, read and write waiting together %ld; "
                "%llu pixels drawn\n",
                cov_wb_back_to_back, cov_wb_cyc_gap, cov_wb_abort, cov_aw_first, cov_w_first, cov_aw_w_same,
                cov_b_stall, cov_r_stall, cov_rw_same_clock, (unsigned long long)batch_pixels);
    for (long c : {cov_wb_back_to_back, cov_wb_cyc_gap, cov_wb_abort, cov_aw_first, cov_w_first, cov_aw_w_same,
                   cov_b_stall, cov_r_stall, cov_rw_same_clock}) {
        if (c == 0) fail(false, "a situation of the coverage line never happened");
    }
    if (batch_pixels == 0) fail(false, "no batch drew a pixel");
    std::printf("bus-slaves: wishbone %ld accesses (%ld refused, %ld batches), axi4-lite %ld accesses "
                "(%ld refused, %ld batches), %llu clocks, seed %llu, %ld protocol errors, %ld failures\n",
                completed[WB], refused[WB], per_proto_batches[WB], completed[AXI], refused[AXI],
                per_proto_batches[AXI], (unsigned long long)cycle_no, (unsigned long long)seed, protocol_errors, failures);
    return failures == 0 ? 0 : 1;
}
