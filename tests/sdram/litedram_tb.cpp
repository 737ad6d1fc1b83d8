// litedram_tb — LiteDRAM's generated controller (soc_rtl/litedram) against the SDRAM chip model
// (cosim/sdram/sdram_chip.h) at the chip's pins: the SoC's SDRAM block (soc_sdram.v, the controller
// inside behind our Wishbone port sdram_wb_burst.v) Verilated (litedram_tb_top.sv), the chip in C++,
// this file the CPU on its two buses.
//
//   litedram_tb [--init ours|litedram] [--words N] [--bursts N] [--seed S] [--idle-us US]
//               [--lag full|half] [--grade 6|7] [--expect-error TEXT]
//
// The run: reset; the power-up sequence through the controller's DFI software interface — ours
// (bsp/soc/sdram/sdram_init.c, the firmware's) or LiteDRAM's generated init_sequence(); N words written
// at seeded random addresses over the whole chip with random byte enables, read back in another
// order and compared; a block of consecutive words written and read as single requests (clocks per
// word, both ways); 8-word read bursts (CTI 010 ... 111, as VexRiscv's caches refill a line) over
// that block and at random lines (first-beat latency, clocks a line) and 8-word write bursts; then
// --bursts N cases mixed at random against a reference memory (burst_cases: line reads and writes,
// single words, bursts abandoned early three ways, unaligned, wrap-8, across the chip's top); then US
// microseconds with one access every ~100 µs, so that the chip sees the controller's refresh alone
// for most of it. The chip model checks every command and timing throughout. A Wishbone beat
// follows the previous one's ack in the next clock, as VexRiscv's bridges present them.
//
// --grade: the chip's speed grade (cosim/sdram/sdram_chip.h: -6 and -7 differ in tRCD, tRP, tRAS,
// tRRD and tWR, each the stricter in some); the controller is set up for both.
// Clocks: the controller's clk and the half-rate PHY's clk2x (twice as fast, rising edges aligned);
// the chip is clocked at clk2x's rate. --lag: where the chip's clock edge falls, zero-delay.
// full (the default): at clk2x's rising edge, with the pins as they were just before it — the chip
// sees each command a whole clk2x period after the PHY's output registers set it, and its data is
// sampled by the PHY at the edge after the one that follows its edge; half: at clk2x's falling
// edge — the chip sees a command half a period after it is set, and its data is on the pins before
// the PHY's next edge. The board's SDRAM clock lags clk2x by the PLL's phase plus the I/O and the
// chip's output delays; which of the two the PHY's read latency expects decides that phase
// (docs/sdram.md).
//
// Exit 0 and a last line `litedram_tb: ok ...` when every read matched and the chip saw no
// violation; with --expect-error TEXT, exit 0 only if the chip reported a violation containing
// TEXT (the tests that show the model catches a controller set up wrongly).
#include <cinttypes>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <random>
#include <string>
#include <unordered_map>
#include <vector>

#include "Vlitedram_tb_top.h"
#include "verilated.h"

#include "sdram_chip.h"
#include "sdram_pins.h"

extern "C" {
#include "sdram_init.h"
uint32_t csr_read_simple(unsigned long addr);
void csr_write_simple(uint32_t value, unsigned long addr);
void litedram_init_sequence(void);  // tests/sdram/litedram_init.c: LiteDRAM's own
void cdelay(int i);
}

namespace {

constexpr uint32_t kSysClkHz = LITEDRAM_TB_SYS_CLK_HZ;
constexpr uint64_t kPsPerClock = 1000000000000ull / kSysClkHz;
constexpr uint32_t kWordAddressBits = 23;        // the user port: 8 M words of 32 bits = 32 MB
constexpr uint64_t kBusTimeoutClocks = 10000;    // a Wishbone request must be answered by then
constexpr uint32_t kCtiClassic = 0, kCtiIncrementing = 2, kCtiEnd = 7;   // Wishbone B4 CTI
constexpr uint32_t kLineWords = 8;               // the caches' line, 32 bytes

struct Bench {
    std::unique_ptr<VerilatedContext> ctx{new VerilatedContext};
    std::unique_ptr<Vlitedram_tb_top> top{new Vlitedram_tb_top{ctx.get()}};
    std::unique_ptr<SdramChip> chip;
    bool lag_full = true;
    uint64_t clocks = 0;
    bool failed = false;

    // One system clock: two of clk2x, clk rising with the first and falling with the second. The
    // chip's edges are clk2x's, at the lag the run asked for (see the header).
    void tick() {
        for (int half = 0; half < 2; ++half) {
            const SdramPins before = sdram_pins_of(*top);  // what a full-lag chip samples
            top->clk2x = 1;
            top->clk = half == 0;
            top->eval();                                   // the PHY samples the chip's old drive
            if (lag_full) {
                sdram_drive(*top, chip->clock(before));
                top->eval();
            }
            top->clk2x = 0;
            top->eval();
            if (!lag_full) {
                sdram_drive(*top, chip->clock(sdram_pins_of(*top)));  // clk2x's falling edge
                top->eval();
            }
        }
        ++clocks;
        if (chip->failed() && !failed) {
            failed = true;
        }
    }

    // A classic Wishbone cycle on one of the two buses; returns the read data. On the SDRAM's bus
    // it is one beat with CTI 000 (beat()). The master ends the cycle after the ack; a next call
    // begins the next cycle without a clock between them.
    uint32_t cycle(bool ctrl_bus, uint32_t adr, bool we, uint32_t dat, uint32_t sel) {
        if (!ctrl_bus) {
            const uint32_t data = beat(adr, we, dat, sel, kCtiClassic);
            top->wb_cyc = 0;
            top->eval();
            return data;
        }
        top->ctrl_adr = adr; top->ctrl_we = we; top->ctrl_dat_w = dat; top->ctrl_sel = sel;
        top->ctrl_cyc = 1; top->ctrl_stb = 1;
        top->eval();
        for (uint64_t n = 0;; ++n) {
            const bool ack = top->ctrl_ack, err = top->ctrl_err;
            const uint32_t data = top->ctrl_dat_r;
            tick();   // the master sees ack at this edge and ends the cycle after it
            if (ack || err) {
                top->ctrl_cyc = 0; top->ctrl_stb = 0;
                top->eval();
                if (err) {
                    std::fprintf(stderr, "litedram_tb: bus error at ctrl word 0x%06x\n", adr);
                    std::exit(1);
                }
                return data;
            }
            check_timeout(n, "ctrl", we, adr);
        }
    }

    // One beat on the SDRAM's bus (cyc and stb high, held until its ack; the next beat, if any,
    // follows in the next clock, as VexRiscv's bridges present it). beat_clocks: the clocks it took
    // (1: acked in its first clock).
    uint32_t beat(uint32_t adr, bool we, uint32_t dat, uint32_t sel, uint32_t cti) {
        top->wb_adr = adr; top->wb_we = we; top->wb_dat_w = dat; top->wb_sel = sel; top->wb_cti = cti;
        top->wb_cyc = 1; top->wb_stb = 1;
        top->eval();
        for (uint64_t n = 0;; ++n) {
            const bool ack = top->wb_ack, err = top->wb_err;
            const uint32_t data = top->wb_dat_r;
            tick();
            if (ack || err) {
                beat_clocks = static_cast<uint32_t>(n + 1);
                top->wb_stb = 0;   // cyc stays: the next beat or request follows at once
                top->eval();
                if (err) {
                    std::fprintf(stderr, "litedram_tb: bus error at user word 0x%06x\n", adr);
                    std::exit(1);
                }
                return data;
            }
            check_timeout(n, "user", we, adr);
        }
    }

    // A read beat offered for one clock only, then withdrawn (stb low, cyc high) whether acked or
    // not (a master may drop a request before its answer); returns whether it was acked.
    bool offer(uint32_t adr, uint32_t cti, uint32_t* data) {
        top->wb_adr = adr; top->wb_we = 0; top->wb_sel = 0xF; top->wb_cti = cti;
        top->wb_cyc = 1; top->wb_stb = 1;
        top->eval();
        const bool ack = top->wb_ack;
        *data = top->wb_dat_r;
        tick();
        top->wb_stb = 0;
        top->eval();
        return ack;
    }

    // The master leaves the SDRAM's bus (cyc low) for n clocks.
    void idle(uint32_t n) {
        top->wb_cyc = 0; top->wb_stb = 0;
        top->eval();
        for (uint32_t i = 0; i < n; ++i) tick();
    }

    void check_timeout(uint64_t n, const char* bus, bool we, uint32_t adr) {
        if (n == kBusTimeoutClocks || failed) {
            std::fprintf(stderr, "litedram_tb: %s bus: no answer to %s of word 0x%06x in %" PRIu64
                         " clocks%s\n", bus, we ? "a write" : "a read", adr, n,
                         failed ? " (the chip model stopped the run)" : "");
            finish_and_exit(1);
        }
    }

    uint32_t read(uint32_t word) { return cycle(false, word, false, 0, 0xF); }
    void write(uint32_t word, uint32_t data, uint32_t sel) { cycle(false, word, true, data, sel); }
    uint32_t beat_clocks = 0;

    [[noreturn]] void finish_and_exit(int status);
};

Bench* bench;
std::string expect_error;

void Bench::finish_and_exit(int status) {
    chip->finish();
    const auto& errors = chip->errors();
    for (size_t i = 0; i < errors.size() && i < 10; ++i) {
        std::fprintf(stderr, "%s\n", errors[i].c_str());
    }
    if (!expect_error.empty()) {
        for (const auto& e : errors) {
            if (e.find(expect_error) != std::string::npos) {
                std::printf("litedram_tb: ok, the chip model caught it: %s\n", e.c_str());
                std::exit(0);
            }
        }
        std::printf("litedram_tb: FAILED: no chip violation mentions '%s' (%zu violations)\n",
                    expect_error.c_str(), errors.size());
        std::exit(1);
    }
    std::exit(status != 0 ? status : (errors.empty() ? 0 : 1));
}

uint32_t apply_sel(uint32_t old_value, uint32_t value, uint32_t sel) {
    uint32_t mask = 0;
    for (int b = 0; b < 4; ++b) {
        if (sel & (1u << b)) {
            mask |= 0xFFu << (8 * b);
        }
    }
    return (old_value & ~mask) | (value & mask);
}


// ---- bursts (sdram_wb_burst): a reference memory of the words written, and the master's beats ----
struct Reference {
    std::unordered_map<uint32_t, uint32_t> words;
    uint32_t mismatches = 0;
    uint32_t beats = 0;     // read beats checked

    void check(uint32_t word, uint32_t got, const char* what) {
        ++beats;
        const auto it = words.find(word);
        const uint32_t want = it == words.end() ? 0xDEADBEEFu : it->second;
        if (it == words.end() || got != want) {
            if (mismatches++ < 8) {
                std::fprintf(stderr, "litedram_tb: %s: word 0x%06x read 0x%08x, expected 0x%08x%s\n", what,
                             word, got, want, it == words.end() ? " (never written)" : "");
            }
        }
    }
};

constexpr uint32_t kWordMask = (1u << kWordAddressBits) - 1;

// A burst of n beats from word `first` (incrementing, the core's addresses wrapping at its top; or
// with wrap_line, BTE wrap-8: the line's words from `first` round to the one before it): CTI 010 on
// every beat but the last, 111 on the last (end_cti, or 010 to leave a burst unfinished).
// Writes: data from rng, lanes sel (0: random lanes per beat). Returns the clocks of its beats.
uint64_t burst(Bench& b, Reference& ref, std::mt19937& rng, uint32_t first, uint32_t n, bool we,
               uint32_t sel, bool wrap_line = false, uint32_t end_cti = kCtiEnd,
               uint64_t* first_beat_clocks = nullptr) {
    uint64_t clocks = 0;
    for (uint32_t i = 0; i < n; ++i) {
        const uint32_t word = wrap_line ? (first & ~(kLineWords - 1)) | ((first + i) & (kLineWords - 1))
                                        : (first + i) & kWordMask;
        const uint32_t cti = i + 1 == n ? end_cti : kCtiIncrementing;
        if (we) {
            const uint32_t value = rng();
            const uint32_t lanes = sel != 0 ? sel : (rng() & 0xFu);
            b.beat(word, true, value, lanes, cti);
            auto it = ref.words.find(word);
            if (it == ref.words.end()) {
                ref.words[word] = value;   // a first write is full (callers' rule: the chip is strict)
            } else {
                it->second = apply_sel(it->second, value, lanes);
            }
        } else {
            ref.check(word, b.beat(word, false, 0, 0xF, cti), wrap_line ? "wrap-8 burst" : "burst");
        }
        clocks += b.beat_clocks;
        if (i == 0 && first_beat_clocks != nullptr) *first_beat_clocks = b.beat_clocks;
    }
    return clocks;
}

// The burst cases against a reference memory, on words the bench writes first (the chip model is
// strict about reads of never-written bytes, and a burst reads its line ahead): REGION words from
// kRegion, mixed at random (seeded) — 8-word bursts at line boundaries read and written, single
// reads and writes (random lanes), bursts abandoned early (CTI 111 before the line's end, cyc
// dropped, another request at once, or a beat offered as the last for one clock, withdrawn, and
// the burst then going on), bursts from the middle of a line running into the next,
// wrap-8 bursts (critical word first), and a burst across the top of the chip into word 0.
constexpr uint32_t kRegion = 0x300000, kRegionWords = 4096;

void burst_cases(Bench& b, Reference& ref, std::mt19937& rng, uint32_t ops, uint32_t counts[8]) {
    for (uint32_t w = 0; w < kRegionWords; w += kLineWords) {
        burst(b, ref, rng, kRegion + w, kLineWords, true, 0xF);
    }
    const uint32_t top = kWordMask + 1 - 2 * kLineWords;   // the chip's last two lines and first two
    burst(b, ref, rng, top, 4 * kLineWords, true, 0xF);
    b.idle(1);
    for (uint32_t n = 0; n < ops; ++n) {
        const uint32_t kind = rng() % 8;
        // a line with two more after it in the region (a burst from its middle may run 16 words)
        const uint32_t line = kRegion + (rng() % (kRegionWords / kLineWords - 2)) * kLineWords;
        const uint32_t offset = rng() % kLineWords;
        ++counts[kind];
        switch (kind) {
        case 0: case 1:   // an aligned 8-word read burst, a line refill
            burst(b, ref, rng, line, kLineWords, false, 0xF);
            break;
        case 2:           // an aligned 8-word write burst, random lanes
            burst(b, ref, rng, line, kLineWords, true, 0);
            break;
        case 3:           // a single read and a single write (random lanes) of one word
            ref.check(line + offset, b.beat(line + offset, false, 0, 0xF, kCtiClassic), "single read");
            burst(b, ref, rng, line + (rng() % kLineWords), 1, true, 0, false, kCtiClassic);
            break;
        case 4: {         // a read burst abandoned after k beats, in one of four ways
            const uint32_t k = 1 + rng() % (kLineWords - 1);
            const uint32_t how = rng() % 4;
            if (how == 3) {   // beat k offered as the last for a clock, withdrawn, then the burst goes on
                burst(b, ref, rng, line, k, false, 0xF, false, kCtiIncrementing);
                uint32_t data = 0;
                if (b.offer(line + k, kCtiEnd, &data)) {
                    ref.check(line + k, data, "beat offered once");
                    break;
                }
                b.tick();
                burst(b, ref, rng, line + k, kLineWords - k, false, 0xF);
                break;
            }
            burst(b, ref, rng, line + (how == 0 ? 0 : offset % (kLineWords - k + 1)), k, false, 0xF, false,
                  how == 0 ? kCtiEnd : kCtiIncrementing);
            if (how == 1) b.idle(rng() % 4);   // cyc dropped (0: the next request at once, cyc high)
            break;
        }
        case 5:           // from the middle of a line, on into the next (up to 2 lines)
            burst(b, ref, rng, line + offset, 1 + rng() % (2 * kLineWords), false, 0xF);
            break;
        case 6:           // wrap-8: the critical word first, then round the line
            burst(b, ref, rng, line + offset, kLineWords, false, 0xF, true);
            break;
        default:          // across the chip's top into word 0
            burst(b, ref, rng, top + kLineWords + offset, kLineWords, false, 0xF);
            break;
        }
        if (rng() % 4 == 0) b.idle(1 + rng() % 3);   // sometimes a gap, sometimes the next at once
    }
    b.idle(1);
}

}  // namespace

// The accessors LiteDRAM's generated csr.h calls (tests/sdram/stub/hw/common.h): byte addresses of
// the control bus, whose Wishbone addresses are words.
extern "C" uint32_t csr_read_simple(unsigned long addr) {
    return bench->cycle(true, static_cast<uint32_t>(addr >> 2), false, 0, 0xF);
}
extern "C" void csr_write_simple(uint32_t value, unsigned long addr) {
    bench->cycle(true, static_cast<uint32_t>(addr >> 2), true, value, 0xF);
}
extern "C" void sdram_delay_ns(uint32_t ns) {
    const uint64_t clocks = (static_cast<uint64_t>(ns) * 1000 + kPsPerClock - 1) / kPsPerClock;
    for (uint64_t i = 0; i < clocks; ++i) {
        bench->tick();
    }
}
// LiteX's cdelay(i): a software loop of i iterations; one clock each is the least it can take.
extern "C" void cdelay(int i) {
    for (int n = 0; n < i; ++n) {
        bench->tick();
    }
}

int main(int argc, char** argv) {
    std::string init = "ours";
    uint32_t words = 2000, seed = 1, idle_us = 0, bursts = 2000;
    std::string lag = "full";
    int grade = 7;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto value = [&]() -> const char* {
            if (i + 1 >= argc) {
                std::fprintf(stderr, "litedram_tb: %s needs a value\n", a.c_str());
                std::exit(2);
            }
            return argv[++i];
        };
        if (a == "--init") init = value();
        else if (a == "--words") words = std::strtoul(value(), nullptr, 0);
        else if (a == "--seed") seed = std::strtoul(value(), nullptr, 0);
        else if (a == "--bursts") bursts = std::strtoul(value(), nullptr, 0);
        else if (a == "--idle-us") idle_us = std::strtoul(value(), nullptr, 0);
        else if (a == "--lag") lag = value();
        else if (a == "--grade") grade = std::atoi(value());
        else if (a == "--expect-error") expect_error = value();
        else {
            std::fprintf(stderr, "litedram_tb: unknown argument %s\n", a.c_str());
            return 2;
        }
    }
    if ((init != "ours" && init != "litedram") || (lag != "full" && lag != "half") || (grade != 6 && grade != 7)) {
        std::fprintf(stderr, "litedram_tb: --init ours|litedram, --lag full|half, --grade 6|7\n");
        return 2;
    }

    Bench b;
    bench = &b;
    b.lag_full = lag == "full";
    SdramConfig cfg = SdramConfig::speed_grade(grade);
    cfg.clock_period_ps = kPsPerClock / 2;   // the chip's clock: clk2x's
    cfg.fail_fast = true;
    cfg.strict_uninitialised_reads = true;
    b.chip.reset(new SdramChip(cfg));

    b.top->rst = 1;
    for (int i = 0; i < 8; ++i) b.tick();
    b.top->rst = 0;
    for (int i = 0; i < 8; ++i) b.tick();

    uint32_t mode = 0;
    if (init == "ours") {
        mode = sdram_init();
    } else {
        litedram_init_sequence();
    }
    if (!b.top->init_done) {
        std::fprintf(stderr, "litedram_tb: init_done is low after the power-up sequence\n");
        b.finish_and_exit(1);
    }
    const uint64_t init_clocks = b.clocks;

    // Random words over the whole chip, random byte enables after the first full write.
    std::mt19937 rng(seed);
    std::unordered_map<uint32_t, uint32_t> shadow;
    std::vector<uint32_t> order;
    const uint64_t random_start = b.clocks;
    for (uint32_t n = 0; n < words; ++n) {
        const uint32_t word = rng() & ((1u << kWordAddressBits) - 1);
        const uint32_t value = rng();
        auto it = shadow.find(word);
        const uint32_t sel = it == shadow.end() ? 0xFu : (rng() & 0xFu);
        b.write(word, value, sel);
        if (it == shadow.end()) {
            shadow[word] = value;
            order.push_back(word);
        } else {
            it->second = apply_sel(it->second, value, sel);
        }
    }
    std::shuffle(order.begin(), order.end(), rng);
    uint32_t mismatches = 0;
    for (uint32_t word : order) {
        const uint32_t got = b.read(word);
        if (got != shadow[word] && mismatches++ < 5) {
            std::fprintf(stderr, "litedram_tb: word 0x%06x read 0x%08x, wrote 0x%08x\n", word, got,
                         shadow[word]);
        }
    }
    const uint64_t random_clocks = b.clocks - random_start;

    // Consecutive words: the cost of one word per Wishbone cycle, written then read.
    constexpr uint32_t kBlock = 1024, kBlockBase = 0x123400;
    const uint64_t wr_start = b.clocks;
    for (uint32_t i = 0; i < kBlock; ++i) b.write(kBlockBase + i, 0x9E3779B9u * (i + 1), 0xF);
    const uint64_t wr_clocks = b.clocks - wr_start;
    const uint64_t rd_start = b.clocks;
    for (uint32_t i = 0; i < kBlock; ++i) {
        const uint32_t got = b.read(kBlockBase + i);
        if (got != 0x9E3779B9u * (i + 1) && mismatches++ < 5) {
            std::fprintf(stderr, "litedram_tb: block word %u read 0x%08x\n", i, got);
        }
    }
    const uint64_t rd_clocks = b.clocks - rd_start;


    // Bursts: 8-word line refills over the consecutive block (rows open: first-beat latency and
    // clocks a line), the same at random lines of a 16 KiB region (a row to open first, mostly),
    // 8-word write bursts; then the mixed cases against the reference memory.
    Reference ref;
    for (uint32_t i = 0; i < kBlock; ++i) ref.words[kBlockBase + i] = 0x9E3779B9u * (i + 1);
    constexpr uint32_t kLines = kBlock / kLineWords;
    uint64_t seq_first = 0, seq_clocks = 0, rnd_first = 0, rnd_clocks = 0;
    for (uint32_t l = 0; l < kLines; ++l) {
        uint64_t first = 0;
        seq_clocks += burst(b, ref, rng, kBlockBase + l * kLineWords, kLineWords, false, 0xF, false, kCtiEnd, &first);
        seq_first += first;
    }
    b.idle(1);
    uint32_t counts[8] = {};
    burst_cases(b, ref, rng, bursts, counts);
    for (uint32_t l = 0; l < kLines; ++l) {
        const uint32_t line = kRegion + (rng() % (kRegionWords / kLineWords)) * kLineWords;
        uint64_t first = 0;
        rnd_clocks += burst(b, ref, rng, line, kLineWords, false, 0xF, false, kCtiEnd, &first);
        rnd_first += first;
        b.idle(1);
    }
    const uint64_t wburst_start = b.clocks;
    for (uint32_t l = 0; l < kLines; ++l) burst(b, ref, rng, kBlockBase + l * kLineWords, kLineWords, true, 0xF);
    b.idle(1);
    const uint64_t wburst_clocks = b.clocks - wburst_start - 1;
    for (uint32_t i = 0; i < kBlock; ++i) ref.check(kBlockBase + i, b.read(kBlockBase + i), "block after write bursts");
    for (uint32_t i = 0; i < kBlock; ++i) b.write(kBlockBase + i, 0x9E3779B9u * (i + 1), 0xF);   // for the idle check
    mismatches += ref.mismatches;

    // Idle: the controller's refresh alone keeps the chip (one read every ~100 µs).
    const uint64_t idle_clocks = static_cast<uint64_t>(idle_us) * 1000000 / kPsPerClock;
    const uint64_t idle_end = b.clocks + idle_clocks;
    const uint64_t poke_every = 100000000 / kPsPerClock;
    while (b.clocks < idle_end && !b.failed) {
        for (uint64_t i = 0; i < poke_every && b.clocks < idle_end; ++i) b.tick();
        if (b.read(kBlockBase) != 0x9E3779B9u && mismatches++ < 5) {
            std::fprintf(stderr, "litedram_tb: block word 0 changed while idle\n");
        }
    }

    b.chip->finish();
    const auto& st = b.chip->stats();
    std::printf("litedram_tb: init %s (mode register 0x%03x) in %" PRIu64 " clocks; %zu random words in %"
                PRIu64 " clocks (%.2f a word, write and read); %u consecutive words: write %.2f, read %.2f"
                " clocks a word\n", init.c_str(), mode, init_clocks, order.size(), random_clocks,
                static_cast<double>(random_clocks) / (2.0 * words), kBlock,
                static_cast<double>(wr_clocks) / kBlock, static_cast<double>(rd_clocks) / kBlock);
    std::printf("litedram_tb: 8-word read bursts: first beat %.2f clocks, %.2f a line, %.2f a word (rows open);"
                " random lines: first beat %.2f, %.2f a line; 8-word write bursts %.2f clocks a word\n",
                static_cast<double>(seq_first) / kLines, static_cast<double>(seq_clocks) / kLines,
                static_cast<double>(seq_clocks) / kBlock, static_cast<double>(rnd_first) / kLines,
                static_cast<double>(rnd_clocks) / kLines, static_cast<double>(wburst_clocks) / kBlock);
    std::printf("litedram_tb: burst cases: %u read beats checked (%u line reads, %u line writes, %u single pairs,"
                " %u abandoned, %u unaligned, %u wrap-8, %u across the top), %u wrong\n", ref.beats,
                counts[0] + counts[1], counts[2], counts[3], counts[4], counts[5], counts[6], counts[7],
                ref.mismatches);
    std::printf("litedram_tb: %" PRIu64 " clocks (%.3f ms) at %.1f MHz, chip at %.1f MHz, lag %s; chip (-%d): %s\n",
                b.clocks, b.clocks * kPsPerClock / 1e9, kSysClkHz / 1e6, 2 * kSysClkHz / 1e6, lag.c_str(), grade,
                st.c_str());
    if (mismatches != 0) {
        std::printf("litedram_tb: FAILED: %u words read back wrong\n", mismatches);
        if (expect_error.empty()) b.finish_and_exit(1);
    }
    if (b.chip->error_count() != 0 || !expect_error.empty()) {
        b.finish_and_exit(b.chip->error_count() != 0 ? 1 : 0);
    }
    std::printf("litedram_tb: ok %zu random and %u consecutive words, %u burst beats, no chip violation\n",
                order.size(), kBlock, ref.beats);
    return 0;
}
