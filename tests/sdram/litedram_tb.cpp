// litedram_tb — LiteDRAM's generated controller (soc_rtl/litedram) against the SDRAM chip model
// (cosim/sdram/sdram_chip.h) at the chip's pins: the SoC's SDRAM block (soc_sdram.v, the controller
// inside) Verilated (litedram_tb_top.sv), the chip in C++, this file the CPU on its two buses.
//
//   litedram_tb [--init ours|litedram] [--words N] [--seed S] [--idle-us US] [--phase 180|0]
//               [--grade 6|7] [--expect-error TEXT]
//
// The run: reset; the power-up sequence through the controller's DFI software interface — ours
// (bsp/soc/sdram/sdram_init.c, the firmware's) or LiteDRAM's generated init_sequence(); N words written
// at seeded random addresses over the whole chip with random byte enables, read back in another
// order and compared; a block of consecutive words written and read (cycles per word, both ways);
// then US microseconds with one access every ~100 µs, so that the chip sees the controller's
// refresh alone for most of it. The chip model checks every command and timing throughout.
//
// --grade: the chip's speed grade (cosim/sdram/sdram_chip.h: -6 and -7 differ in tRCD, tRP, tRAS,
// tRRD and tWR, each the stricter in some); the controller is set up for both.
// --phase: where the chip's clock edge falls in the system clock's period. 180: on its falling
// edge (the chip samples what the controller's output registers set half a period before, and its
// data is back before the controller's next rising edge); 0: on the rising edge itself (the chip
// sees each command a full clock later). The board's PLL phase follows from which of the two the
// controller's read latency expects (docs/sdram.md).
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

struct Bench {
    std::unique_ptr<VerilatedContext> ctx{new VerilatedContext};
    std::unique_ptr<Vlitedram_tb_top> top{new Vlitedram_tb_top{ctx.get()}};
    std::unique_ptr<SdramChip> chip;
    int phase = 180;
    uint64_t clocks = 0;
    bool failed = false;

    // One system clock. The chip's edge falls at the phase the run asked for (see the header).
    void tick() {
        if (phase == 0) {
            const SdramPins before = sdram_pins_of(*top);  // what the chip samples at the shared edge
            top->clk = 1;
            top->eval();                         // the controller samples the chip's old drive
            sdram_drive(*top, chip->clock(before));
            top->eval();
            top->clk = 0;
            top->eval();
        } else {
            top->clk = 1;
            top->eval();
            top->clk = 0;
            top->eval();
            sdram_drive(*top, chip->clock(sdram_pins_of(*top)));  // the falling edge: the chip's rising edge
            top->eval();
        }
        ++clocks;
        if (chip->failed() && !failed) {
            failed = true;
        }
    }

    // A classic Wishbone cycle on one of the two buses; returns the read data.
    uint32_t cycle(bool ctrl_bus, uint32_t adr, bool we, uint32_t dat, uint32_t sel) {
        auto set = [&](uint32_t cyc) {
            if (ctrl_bus) {
                top->ctrl_adr = adr; top->ctrl_we = we; top->ctrl_dat_w = dat; top->ctrl_sel = sel;
                top->ctrl_cyc = cyc; top->ctrl_stb = cyc;
            } else {
                top->wb_adr = adr; top->wb_we = we; top->wb_dat_w = dat; top->wb_sel = sel;
                top->wb_cyc = cyc; top->wb_stb = cyc;
            }
        };
        set(1);
        top->eval();
        for (uint64_t n = 0;; ++n) {
            const bool ack = ctrl_bus ? top->ctrl_ack : top->wb_ack;
            const bool err = ctrl_bus ? top->ctrl_err : top->wb_err;
            const uint32_t data = ctrl_bus ? top->ctrl_dat_r : top->wb_dat_r;
            tick();   // the master sees ack at this edge and ends the cycle after it
            if (ack || err) {
                set(0);
                top->eval();
                if (err) {
                    std::fprintf(stderr, "litedram_tb: bus error at %s word 0x%06x\n",
                                 ctrl_bus ? "ctrl" : "user", adr);
                    std::exit(1);
                }
                return data;
            }
            if (n == kBusTimeoutClocks || failed) {
                std::fprintf(stderr, "litedram_tb: %s bus: no answer to %s of word 0x%06x in %" PRIu64
                             " clocks%s\n", ctrl_bus ? "ctrl" : "user", we ? "a write" : "a read", adr, n,
                             failed ? " (the chip model stopped the run)" : "");
                finish_and_exit(1);
            }
        }
    }

    uint32_t read(uint32_t word) { return cycle(false, word, false, 0, 0xF); }
    void write(uint32_t word, uint32_t data, uint32_t sel) { cycle(false, word, true, data, sel); }

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
    uint32_t words = 2000, seed = 1, idle_us = 0;
    int phase = 180, grade = 7;
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
        else if (a == "--idle-us") idle_us = std::strtoul(value(), nullptr, 0);
        else if (a == "--phase") phase = std::atoi(value());
        else if (a == "--grade") grade = std::atoi(value());
        else if (a == "--expect-error") expect_error = value();
        else {
            std::fprintf(stderr, "litedram_tb: unknown argument %s\n", a.c_str());
            return 2;
        }
    }
    if ((init != "ours" && init != "litedram") || (phase != 0 && phase != 180) || (grade != 6 && grade != 7)) {
        std::fprintf(stderr, "litedram_tb: --init ours|litedram, --phase 180|0, --grade 6|7\n");
        return 2;
    }

    Bench b;
    bench = &b;
    b.phase = phase;
    SdramConfig cfg = SdramConfig::speed_grade(grade);
    cfg.clock_period_ps = kPsPerClock;
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
    std::printf("litedram_tb: %" PRIu64 " clocks (%.3f ms) at %.1f MHz, phase %d; chip (-%d): %s\n", b.clocks,
                b.clocks * kPsPerClock / 1e9, kSysClkHz / 1e6, phase, grade, st.c_str());
    if (mismatches != 0) {
        std::printf("litedram_tb: FAILED: %u words read back wrong\n", mismatches);
        if (expect_error.empty()) b.finish_and_exit(1);
    }
    if (b.chip->error_count() != 0 || !expect_error.empty()) {
        b.finish_and_exit(b.chip->error_count() != 0 ? 1 : 0);
    }
    std::printf("litedram_tb: ok %zu random and %u consecutive words, no chip violation\n", order.size(), kBlock);
    return 0;
}
