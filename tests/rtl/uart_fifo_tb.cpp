// uart_fifo_tb: soc_uart on its own, with the contract's parameters (SOC_CLK_HZ_DEFAULT,
// SOC_UART_BAUD, SOC_UART_RX_FIFO_DEPTH), its RX FIFO at depth through the real 8N1 line
// (cosim/soc/uart_line's sender, the codec the SoC testbenches use) and its Wishbone slave:
//   - after reset: STATUS RX_VALID clear, a DATA read answers 0, ERRORS 0;
//   - 1000 bytes in and out, so that the next fill wraps the RAM's pointers in the middle;
//   - the FIFO filled to SOC_UART_RX_FIFO_DEPTH exactly and one byte more: that one is the only
//     overrun; after one pop there is room for one byte again, and the next is an overrun once more;
//     every byte read back in order across the wrap, then empty;
//   - streaming: twice the depth and more sent while a reader with random gaps polls STATUS and
//     DATA: every byte in order, no new overrun;
//   - the bus, on every access: ack (never err) in the clock after the request's first clock, not
//     again in the next one; a DATA read with VALID pops exactly one byte.
//     uart_fifo_tb [SEED]      (built by tests/rtl/uart_fifo.sh)
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <random>
#include <string>

#include "Vsoc_uart.h"
#include "soc_map.h"
#include "uart_line.h"
#include "verilated.h"

static Vsoc_uart *top;
static UartLineSender *line;
static std::mt19937 rng;
static uint64_t cycle_no = 0;
static long failures = 0;

#define CHECK(cond, ...)                                                                  \
    do {                                                                                  \
        if (!(cond)) {                                                                    \
            if (++failures <= 20) {                                                       \
                std::printf("uart_fifo_tb: cycle %llu: ", (unsigned long long)cycle_no);  \
                std::printf(__VA_ARGS__);                                                 \
                std::printf("\n");                                                        \
            }                                                                             \
        }                                                                                 \
    } while (0)

// One system clock: the line's level for it, then the rising edge.
static void tick()
{
    top->uart_rx_async = line->tick();
    top->clk = 1;
    top->eval();
    top->clk = 0;
    top->eval();
    cycle_no++;
}

static void idle(uint32_t clocks)
{
    top->wb_cyc = top->wb_stb = 0;
    for (uint32_t i = 0; i < clocks; i++) {
        tick();
    }
}

// One Wishbone access, held through its ack clock (a master that sees ack drops STB at that
// clock's end, or starts its next request right after it: back to back when no idle() follows).
static uint32_t access(bool we, uint32_t off, uint32_t data)
{
    top->wb_cyc = top->wb_stb = 1;
    top->wb_we = we;
    top->wb_adr = off >> 2;
    top->wb_dat_w = data & 0xFFu;
    tick();   // the request's first clock
    CHECK(top->wb_ack && !top->wb_err, "offset 0x%x: ack %d err %d in the clock after the request", off,
          top->wb_ack, top->wb_err);
    const uint32_t r = top->wb_dat_r;
    tick();   // the ack clock: the request's effects must not repeat
    CHECK(!top->wb_ack && !top->wb_err, "offset 0x%x: answered twice", off);
    top->wb_cyc = top->wb_stb = 0;
    return r;
}

static uint32_t rd(uint32_t off) { return access(false, off, 0); }
static uint32_t overruns() { return (rd(SOC_UART_REG_ERRORS) & SOC_UART_ERRORS_OVERRUN_MASK) >> SOC_UART_ERRORS_OVERRUN_LSB; }
static uint32_t framing() { return (rd(SOC_UART_REG_ERRORS) & SOC_UART_ERRORS_FRAMING_MASK) >> SOC_UART_ERRORS_FRAMING_LSB; }
static bool rx_valid() { return rd(SOC_UART_REG_STATUS) & SOC_UART_STATUS_RX_VALID_MASK; }

// Queues n random bytes on the line; returns them.
static std::deque<uint8_t> send(size_t n)
{
    std::deque<uint8_t> bytes;
    std::string s;
    for (size_t i = 0; i < n; i++) {
        bytes.push_back(uint8_t(rng()));
        s += char(bytes.back());
    }
    line->queue(s);
    return bytes;
}

// Until the last queued byte has left the line, and its stop bit has been sampled.
static void drain_line(uint32_t bit_clocks)
{
    while (line->busy()) {
        tick();
    }
    idle(2 * bit_clocks);
}

// Reads n bytes back to back; each must be VALID and the next of `want`.
static void read_expect(std::deque<uint8_t> &want, size_t n, const char *phase)
{
    for (size_t i = 0; i < n; i++) {
        const uint32_t d = rd(SOC_UART_REG_DATA);
        const uint32_t expect = SOC_UART_DATA_VALID_MASK | (want.empty() ? 0u : want.front());
        CHECK(d == expect, "%s: byte %zu read 0x%03x, expected 0x%03x", phase, i, d, expect);
        if (!want.empty()) {
            want.pop_front();
        }
    }
}

static void expect_empty(const char *phase)
{
    CHECK(!rx_valid(), "%s: STATUS RX_VALID set, the FIFO should be empty", phase);
    const uint32_t d = rd(SOC_UART_REG_DATA);
    CHECK(d == 0, "%s: a DATA read of the empty FIFO answered 0x%x", phase, d);
}

int main(int argc, char **argv)
{
    Verilated::commandArgs(argc, argv);
    rng.seed(argc > 1 ? uint32_t(strtoul(argv[1], nullptr, 0)) : 1u);
    const uint32_t depth = SOC_UART_RX_FIFO_DEPTH;
    const uint32_t bit_clocks = (SOC_CLK_HZ_DEFAULT + SOC_UART_BAUD / 2) / SOC_UART_BAUD;   // soc_uart's DIV
    line = new UartLineSender(bit_clocks);
    top = new Vsoc_uart;
    const auto t0 = std::chrono::steady_clock::now();

    top->uart_rx_async = 1;
    top->rst = 1;
    idle(4);
    top->rst = 0;
    idle(4);

    // After reset.
    CHECK(rd(SOC_UART_REG_DIVIDER) == bit_clocks, "DIVIDER");
    CHECK(rd(SOC_UART_REG_ERRORS) == 0, "ERRORS after reset");
    expect_empty("reset");

    // 1000 in and out: the RAM's pointers now stand in the middle of it.
    std::deque<uint8_t> want = send(1000);
    drain_line(bit_clocks);
    read_expect(want, 1000, "first 1000");
    expect_empty("first 1000");

    // Full to the byte, and one more: one overrun, the byte dropped.
    want = send(depth + 1);
    want.pop_back();   // the dropped one
    drain_line(bit_clocks);
    CHECK(overruns() == 1, "fill: %u overruns, expected 1 (depth %u + 1 bytes sent)", overruns(), depth);
    CHECK(rx_valid(), "fill: RX_VALID clear");
    read_expect(want, 1, "fill, first pop");
    std::deque<uint8_t> more = send(1);   // fits: one byte was popped
    want.push_back(more.front());
    drain_line(bit_clocks);
    CHECK(overruns() == 1, "refill: %u overruns, expected 1 (one byte popped made room for one)", overruns());
    send(1);                              // full again: dropped
    drain_line(bit_clocks);
    CHECK(overruns() == 2, "full again: %u overruns, expected 2", overruns());
    read_expect(want, depth, "full FIFO, across the wrap");
    expect_empty("full FIFO read");

    // Streaming through several wraps: a reader with random gaps (on average well under a byte's
    // time of 10 bits, so that it keeps up) polls STATUS then DATA, or DATA alone.
    const size_t stream = 2 * depth + 100;
    want = send(stream);
    size_t got = 0;
    while (got < stream && cycle_no < 400000000ull) {
        const uint32_t r = rng() % 100;
        idle(r < 40 ? 0 : r < 90 ? rng() % 64 : rng() % (8 * bit_clocks));
        if ((rng() & 1) && !rx_valid()) {
            continue;
        }
        const uint32_t d = rd(SOC_UART_REG_DATA);
        if (!(d & SOC_UART_DATA_VALID_MASK)) {
            CHECK(d == 0, "stream: a DATA read without VALID answered 0x%x", d);
            continue;
        }
        CHECK(!want.empty() && d == (SOC_UART_DATA_VALID_MASK | want.front()), "stream: byte %zu read 0x%03x, expected 0x%03x",
              got, d, want.empty() ? 0u : SOC_UART_DATA_VALID_MASK | want.front());
        if (!want.empty()) {
            want.pop_front();
        }
        got++;
    }
    CHECK(got == stream, "stream: %zu of %zu bytes read", got, stream);
    drain_line(bit_clocks);
    expect_empty("stream");
    CHECK(overruns() == 2, "stream: %u overruns, expected still 2", overruns());
    CHECK(framing() == 0, "framing errors: %u", framing());

    const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    top->final();
    if (failures) {
        std::printf("uart_fifo_tb: FAILED, %ld checks\n", failures);
        return 1;
    }
    std::printf("uart_fifo_tb: RX FIFO depth %u: filled exactly (the %uth byte an overrun), order kept across the wrap, "
                "%zu bytes streamed; %llu clocks in %.2f s\n",
                depth, depth + 1, stream, (unsigned long long)cycle_no, secs);
    return 0;
}
