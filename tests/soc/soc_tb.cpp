// soc_tb: the Verilated soc_top on its own — clocks it, decodes uart_tx at the real baud rate onto
// stdout, can answer a prompt on uart_rx, and ends on the SoC's exit port.
//
//   soc_sim +ram_init=PROGRAM.hex [--max-cycles N] [--reply PROMPT=TEXT] [--quiet]
//
// +ram_init loads the RAM image (tools/elf_to_hex.py) at time 0 (soc_ram's plusarg). --reply: once
// the received text ends with PROMPT, TEXT is sent to uart_rx, 8N1 at the baud rate (\n is a
// newline, \f a frame with a low stop bit); several --reply options may be given. The summary
// goes to stderr as key=value lines: exit_valid, exit_code, cycles, wall_seconds,
// cycles_per_second, cpu_seconds, cycles_per_cpu_second, uart_framing_errors, leds, vga_frames
// (vertical syncs seen). Exit status: the SoC's exit code, or 124 when --max-cycles (default
// 100 M) pass first.
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <cstring>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "Vsoc_top.h"
#include "soc_map.h"
#include "uart_line.h"
#include "verilated.h"

namespace {

std::string unescape(const char *s)
{
    std::string out;
    for (; *s; s++) {
        if (s[0] == '\\' && s[1] == 'n') {
            out += '\n';
            s++;
        } else if (s[0] == '\\' && s[1] == 'f') {
            out += '\f';   // sent as a frame with a low stop bit
            s++;
        } else {
            out += *s;
        }
    }
    return out;
}

}  // namespace

int main(int argc, char **argv)
{
    Verilated::commandArgs(argc, argv);   // +ram_init=FILE reaches soc_ram
    uint64_t max_cycles = 100000000ull;
    std::vector<std::pair<std::string, std::string>> replies;   // prompt, text
    bool quiet = false;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--max-cycles") && i + 1 < argc) {
            max_cycles = strtoull(argv[++i], nullptr, 0);
        } else if (!strcmp(argv[i], "--reply") && i + 1 < argc) {
            std::string arg = unescape(argv[++i]);
            size_t eq = arg.find('=');
            if (eq == std::string::npos) {
                fprintf(stderr, "soc_tb: --reply wants PROMPT=TEXT\n");
                return 2;
            }
            replies.emplace_back(arg.substr(0, eq), arg.substr(eq + 1));
        } else if (!strcmp(argv[i], "--quiet")) {
            quiet = true;
        } else if (argv[i][0] != '+') {
            fprintf(stderr, "usage: %s +ram_init=FILE.hex [--max-cycles N] [--reply PROMPT=TEXT] [--quiet]\n", argv[0]);
            return 2;
        }
    }

    // The RTL's divider (soc_uart: CLK_HZ / BAUD, rounded), as socsim decodes the line.
    const uint32_t bit_clocks = (SOC_CLK_HZ_DEFAULT + SOC_UART_BAUD / 2) / SOC_UART_BAUD;
    UartLineDecoder rx(bit_clocks);
    UartLineSender tx(bit_clocks);
    std::string text;

    auto top = std::make_unique<Vsoc_top>();
    top->clk = top->clk_pix = 0;  // the scan-out's clock tied to the system clock (soc.mk)
    top->ext_rst = 0;
    top->uart_rx = 1;
    top->eval();

    auto t0 = std::chrono::steady_clock::now();
    std::clock_t c0 = std::clock();
    uint64_t cycle = 0, vga_frames = 0;
    bool vsync_n = true;
    for (; cycle < max_cycles && !top->exit_valid; cycle++) {
        top->clk = top->clk_pix = 1;
        top->eval();
        top->clk = top->clk_pix = 0;
        top->eval();
        uint8_t c;
        if (rx.sample(top->uart_tx, &c)) {
            text += (char)c;
            if (!quiet) {
                putchar(c);
                fflush(stdout);
            }
            for (const auto &[prompt, reply] : replies) {
                if (!prompt.empty() && text.size() >= prompt.size() &&
                    text.compare(text.size() - prompt.size(), prompt.size(), prompt) == 0) {
                    for (const char r : reply) {
                        if (r == '\f') {
                            tx.queue_bad_stop(0x55);
                        } else {
                            tx.queue(std::string(1, r));
                        }
                    }
                }
            }
        }
        top->uart_rx = tx.tick();
        if (vsync_n && !top->vga_vsync_n) {
            vga_frames++;   // the GPU's scan-out runs: one vertical sync a frame
        }
        vsync_n = top->vga_vsync_n;
    }
    double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    double cpu = (double)(std::clock() - c0) / CLOCKS_PER_SEC;   // the rate on a shared machine

    fprintf(stderr, "exit_valid=%d\nexit_code=%d\ncycles=%llu\nwall_seconds=%.2f\ncycles_per_second=%.0f\n"
            "cpu_seconds=%.2f\ncycles_per_cpu_second=%.0f\n"
            "uart_framing_errors=%u\nleds=0x%02x\nvga_frames=%llu\n",
            (int)top->exit_valid, (int)top->exit_code, (unsigned long long)cycle, wall,
            wall > 0 ? cycle / wall : 0.0, cpu, cpu > 0 ? cycle / cpu : 0.0, rx.framing_errors(), (unsigned)top->leds,
            (unsigned long long)vga_frames);
    int status = top->exit_valid ? (int)top->exit_code : 124;
    top->final();
    return status;
}
