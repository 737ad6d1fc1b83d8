/* The SoC smoke program: proves soc_top runs code from its RAM and that every block answers as
 * contract/soc-memory-map.md says, without the firmware's BSP. Bare metal, no C library.
 *
 * Prints over the UART (the testbench checks the text): hello; SYS ID, CLK_HZ, RAM_BYTES and the
 * UART divider; the GPU's ID through its Wishbone slave; then provokes and checks each kind of bus error (a load and a store to unmapped
 * I/O addresses, a cached line refill beyond the RAM, an instruction fetch from nowhere, a byte store to the GPU), a timer
 * interrupt, the UART's receiver (the testbench answers "rx?" with 'Z', "burst?" with RX_BURST
 * bytes for an overrun, "break?" with a frame whose stop bit is low), and the LEDs; returns 0 (to
 * SYS EXIT) when all passed, 1 at the first failure. */
#include <stdint.h>

#include "gpu_regs.h"
#include "soc_map.h"

#define SOC_REG(base, off) (*(volatile uint32_t *)(uintptr_t)((base) + (off)))
#define UART(r) SOC_REG(SOC_UART_BASE, SOC_UART_REG_##r)
#define SYS(r) SOC_REG(SOC_SYS_BASE, SOC_SYS_REG_##r)

/* The overrun test's burst: 4 bytes more than the RX FIFO holds, 'A' + i % 26 for byte i
 * (tests/soc/smoke.sh makes the testbench's reply from the same contract value). */
#define RX_BURST (SOC_UART_RX_FIFO_DEPTH + 4u)

#define MCAUSE_ILLEGAL 2u
#define MCAUSE_TIMER 0x80000007u
#define MCAUSE_EXTERNAL 0x8000000Bu
#define MSTATUS_MIE (1u << 3)
#define MIE_MTIE (1u << 7)
#define MIE_MEIE (1u << 11)

#define CSR_READ(csr, v) __asm__ volatile("csrr %0, " #csr : "=r"(v))
#define CSR_WRITE(csr, v) __asm__ volatile("csrw " #csr ", %0" ::"r"(v))
#define CSR_SET(csr, v) __asm__ volatile("csrs " #csr ", %0" ::"r"(v))

/* What the trap handler saw. */
static volatile uint32_t n_external, n_timer, n_illegal, n_other;
static volatile uint32_t last_epc, be_status, be_addr;
volatile uint32_t recover_pc; /* where an illegal-instruction trap resumes (set by the fetch test) */

static void uart_putc(char c)
{
    while (UART(STATUS) & SOC_UART_STATUS_TX_FULL_MASK) {
    }
    UART(DATA) = (uint8_t)c;
}

static void uart_puts(const char *s)
{
    while (*s) {
        uart_putc(*s++);
    }
}

static void uart_hex(uint32_t v)
{
    for (int i = 28; i >= 0; i -= 4) {
        uart_putc("0123456789abcdef"[(v >> i) & 15u]);
    }
}

static void uart_dec(uint32_t v)
{
    char buf[11];
    int n = 0;
    do {
        buf[n++] = (char)('0' + v % 10u);
        v /= 10u;
    } while (v);
    while (n) {
        uart_putc(buf[--n]);
    }
}

/* Waits until everything written has left the pin. */
static void uart_flush(void)
{
    while (!(UART(STATUS) & SOC_UART_STATUS_TX_IDLE_MASK)) {
    }
}

void smoke_exit(uint32_t code)
{
    uart_flush();
    SYS(EXIT) = code;
    for (;;) {
    }
}

static int fail(const char *what, uint32_t got)
{
    uart_puts("soc: FAIL ");
    uart_puts(what);
    uart_puts(" got ");
    uart_hex(got);
    uart_puts("\n");
    return 1;
}

__attribute__((interrupt("machine"), aligned(4))) void smoke_trap(void)
{
    uint32_t cause, epc;
    CSR_READ(mcause, cause);
    CSR_READ(mepc, epc);
    last_epc = epc;
    if (cause == MCAUSE_EXTERNAL) {
        be_status = SYS(BUS_ERR);
        be_addr = SYS(BUS_ERR_ADDR);
        SYS(BUS_ERR) = 0;   /* clears the record and the interrupt line */
        (void)SYS(BUS_ERR); /* a read-back: the clear has landed before mret */
        n_external++;
    } else if (cause == MCAUSE_TIMER) {
        SYS(MTIMECMP_HI) = 0xFFFFFFFFu;
        SYS(MTIMECMP_LO) = 0xFFFFFFFFu;
        n_timer++;
    } else if (cause == MCAUSE_ILLEGAL && recover_pc) {
        CSR_WRITE(mepc, recover_pc);
        recover_pc = 0;
        n_illegal++;
    } else {
        n_other++;
        uart_puts("soc: FAIL unexpected trap mcause ");
        uart_hex(cause);
        uart_puts(" mepc ");
        uart_hex(epc);
        uart_puts("\n");
        smoke_exit(2);
    }
}

/* Waits (boundedly) until *counter passes `before`. */
static int wait_for(volatile uint32_t *counter, uint32_t before)
{
    for (uint32_t i = 0; i < 100000u; i++) {
        if (*counter != before) {
            return 1;
        }
    }
    return 0;
}

static uint64_t mtime(void)
{
    uint32_t lo = SYS(MTIME_LO);
    uint32_t hi = SYS(MTIME_HI);
    return ((uint64_t)hi << 32) | lo;
}

/* One bus error: `access` touches an unmapped address; the external interrupt must follow with
 * the expected record. */
static int check_bus_error(const char *name, void (*access)(void), uint32_t addr, uint32_t status_bits,
                           uint32_t count)
{
    uint32_t before = n_external;
    access();
    if (!wait_for(&n_external, before)) {
        return fail(name, 0xDEAD0001u);
    }
    uint32_t flags = be_status & (SOC_SYS_BUS_ERR_VALID_MASK | SOC_SYS_BUS_ERR_WRITE_MASK | SOC_SYS_BUS_ERR_FETCH_MASK);
    uint32_t n = (be_status & SOC_SYS_BUS_ERR_COUNT_MASK) >> SOC_SYS_BUS_ERR_COUNT_LSB;
    if (be_addr != addr) {
        return fail(name, be_addr);
    }
    if (flags != (SOC_SYS_BUS_ERR_VALID_MASK | status_bits) || n != count) {
        return fail(name, be_status);
    }
    uart_puts("soc: ");
    uart_puts(name);
    uart_puts(" ok (addr ");
    uart_hex(be_addr);
    uart_puts(", ");
    uart_dec(n);
    uart_puts(" refused)\n");
    return 0;
}

#define UNMAPPED_IO 0x90000000u
static volatile uint32_t sink;
static void load_unmapped(void) { sink = SOC_REG(UNMAPPED_IO, 0); }
static void store_unmapped(void) { SOC_REG(SOC_SYS_BASE + SOC_SYS_WINDOW_BYTES, 0) = 0x12345678u; }
static void refill_beyond_ram(void) { sink = SOC_REG(SOC_RAM_BASE + SOC_RAM_DEFAULT_BYTES, 0); }
#define SYS_HOLE 0x14u /* between LEDS and MTIME_LO */
static void load_sys_hole(void) { sink = SOC_REG(SOC_SYS_BASE, SYS_HOLE); }
/* The GPU takes whole words only: a byte store is refused (gpu_wb_slave). */
static void gpu_byte_store(void) { *(volatile uint8_t *)(uintptr_t)(SOC_GPU_BASE + GPU_WIN_PALETTE) = 0x5Au; }

int main(void)
{
    uart_puts("soc: hello\n");

    uint32_t id = SYS(ID), clk = SYS(CLK_HZ), ram = SYS(RAM_BYTES), div = UART(DIVIDER);
    uart_puts("soc: id ");
    uart_hex(id);
    uart_puts(" clk ");
    uart_dec(clk);
    uart_puts(" ram ");
    uart_dec(ram);
    uart_puts(" div ");
    uart_dec(div);
    uart_puts("\n");
    if (id != SOC_SYS_ID_VALUE) {
        return fail("SYS ID", id);
    }
    if (div != (clk + SOC_UART_BAUD / 2) / SOC_UART_BAUD) {
        return fail("UART DIVIDER", div);
    }
    if (SYS(EXIT) != 0) {
        return fail("EXIT reads 0", 1);
    }
    uint32_t gpu_id = SOC_REG(SOC_GPU_BASE, GPU_REG_ID);
    uart_puts("soc: gpu id ");
    uart_hex(gpu_id);
    uart_puts("\n");
    if (gpu_id != GPU_ID_VALUE) {
        return fail("GPU ID", gpu_id);
    }

    /* Traps: the handler, then machine external (bus errors) and timer interrupts. */
    CSR_WRITE(mtvec, (uint32_t)(uintptr_t)&smoke_trap);
    uint32_t mask = 1u << SOC_IRQ_BUS_ERROR;
    __asm__ volatile("csrs 0xBC0, %0" ::"r"(mask)); /* SOC_CSR_IRQ_MASK */
    CSR_SET(mie, MIE_MEIE | MIE_MTIE);
    CSR_SET(mstatus, MSTATUS_MIE);

    if (check_bus_error("load fault", load_unmapped, UNMAPPED_IO, 0, 1) ||
        check_bus_error("store fault", store_unmapped, SOC_SYS_BASE + SOC_SYS_WINDOW_BYTES,
                        SOC_SYS_BUS_ERR_WRITE_MASK, 1) ||
        check_bus_error("refill fault", refill_beyond_ram, SOC_RAM_BASE + SOC_RAM_DEFAULT_BYTES, 0, 8)) {
        return 1;
    }
    if (sink != 0) {
        return fail("refused loads read 0", sink);
    }
    /* An offset inside SYS that names no register is refused too. */
    if (check_bus_error("SYS hole", load_sys_hole, SOC_SYS_BASE + SYS_HOLE, 0, 1) ||
        check_bus_error("GPU byte store", gpu_byte_store, SOC_GPU_BASE + GPU_WIN_PALETTE, SOC_SYS_BUS_ERR_WRITE_MASK, 1)) {
        return 1;
    }

    /* A fetch from nowhere reads 0x00000000, an illegal instruction; the bus error is recorded. */
    uint32_t ill = n_illegal, ext = n_external;
    __asm__ volatile("la   t0, 1f\n"
                     "sw   t0, recover_pc, t1\n"
                     "li   t0, 0x90001000\n"
                     "jalr ra, t0, 0\n"
                     "1:\n" ::: "t0", "t1", "ra", "memory");
    if (!wait_for(&n_external, ext)) {
        return fail("fetch fault: no bus-error interrupt", be_status);
    }
    if (n_illegal != ill + 1 || last_epc == 0) {
        return fail("fetch fault: illegal instruction", n_illegal);
    }
    if (be_addr != 0x90001000u || !(be_status & SOC_SYS_BUS_ERR_FETCH_MASK)) {
        return fail("fetch fault record", be_addr);
    }
    uart_puts("soc: fetch fault ok (illegal instruction, addr ");
    uart_hex(be_addr);
    uart_puts(")\n");

    /* The timer: an interrupt 2000 clocks from now. */
    uint32_t t = n_timer;
    uint64_t when = mtime() + 2000u;
    SYS(MTIMECMP_HI) = 0xFFFFFFFFu;
    SYS(MTIMECMP_LO) = (uint32_t)when;
    SYS(MTIMECMP_HI) = (uint32_t)(when >> 32);
    if (!wait_for(&n_timer, t)) {
        return fail("timer interrupt", (uint32_t)mtime());
    }
    if (mtime() < when) {
        return fail("timer early", (uint32_t)mtime());
    }
    uart_puts("soc: timer ok\n");

    /* The UART's receiver: the testbench sends 'Z' after "rx?". */
    uart_puts("soc: rx?\n");
    uart_flush(); /* the testbench answers once it has seen the prompt */
    uint64_t deadline = mtime() + 20u * 10u * div;   /* 20 character times */
    while (!(UART(STATUS) & SOC_UART_STATUS_RX_VALID_MASK)) {
        if (mtime() > deadline) {
            return fail("rx timeout", UART(STATUS));
        }
    }
    uint32_t d = UART(DATA);
    if (!(d & SOC_UART_DATA_VALID_MASK) || (d & SOC_UART_DATA_BYTE_MASK) != 'Z') {
        return fail("rx byte", d);
    }
    if (UART(DATA) & SOC_UART_DATA_VALID_MASK) {
        return fail("rx pop", d);
    }
    if (UART(ERRORS) != 0) {
        return fail("uart errors", UART(ERRORS));
    }
    uart_puts("soc: rx Z ok\n");

    /* Overrun: RX_BURST bytes arrive unread; the FIFO keeps the first SOC_UART_RX_FIFO_DEPTH. */
    uart_puts("soc: burst?\n");
    uart_flush(); /* the testbench answers once it has seen the prompt */
    uint64_t until = mtime() + (uint64_t)(RX_BURST + 10u) * 10u * div;   /* the reply's frames and some */
    while (mtime() < until) {
    }
    uint32_t overruns = (UART(ERRORS) & SOC_UART_ERRORS_OVERRUN_MASK) >> SOC_UART_ERRORS_OVERRUN_LSB;
    if (overruns != RX_BURST - SOC_UART_RX_FIFO_DEPTH) {
        return fail("rx overruns", UART(ERRORS));
    }
    for (uint32_t i = 0; i < SOC_UART_RX_FIFO_DEPTH; i++) {
        d = UART(DATA);
        if (d != (SOC_UART_DATA_VALID_MASK | ('A' + i % 26u))) {
            return fail("rx FIFO order", d);
        }
    }
    if (UART(STATUS) & SOC_UART_STATUS_RX_VALID_MASK) {
        return fail("rx FIFO drained", UART(STATUS));
    }
    uart_puts("soc: rx overrun ok (");
    uart_dec(overruns);
    uart_puts(" dropped)\n");

    /* Framing: a frame with a low stop bit is counted and dropped. */
    uart_puts("soc: break?\n");
    uart_flush(); /* the testbench answers once it has seen the prompt */
    until = mtime() + 20u * 10u * div;
    while (!(UART(ERRORS) & SOC_UART_ERRORS_FRAMING_MASK)) {
        if (mtime() > until) {
            return fail("framing error not counted", UART(ERRORS));
        }
    }
    if ((UART(ERRORS) & SOC_UART_ERRORS_FRAMING_MASK) >> SOC_UART_ERRORS_FRAMING_LSB != 1u ||
        (UART(STATUS) & SOC_UART_STATUS_RX_VALID_MASK)) {
        return fail("framing error", UART(ERRORS));
    }
    uart_puts("soc: rx framing ok\n");

    SYS(LEDS) = 0xA5u;
    if (SYS(LEDS) != 0xA5u) {
        return fail("LEDS", SYS(LEDS));
    }
    if (n_other != 0) {
        return fail("other traps", n_other);
    }
    uart_puts("soc: done\n");
    return 0;
}
