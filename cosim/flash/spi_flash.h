// SpiFlash: a model of the ULX3S's SPI NOR configuration flash, ISSI IS25LP128 (128 Mbit = 16 MiB,
// 256-byte pages, 4 KiB sectors), at its pins — CS#, SCK, SI (MOSI), SO (MISO) — for the simulators:
// socsim calls step() every half clock with the pins the SoC drives; the model answers on MISO and
// checks every command against the data sheet. Standard SPI only (no dual/quad/QPI/DTR). C++17, no
// Verilator dependency; the model shares nothing with the RTL that reads it (soc_rtl/soc_spiflash.v).
//
// Source: ISSI IS25LP128 "128Mb 3V serial flash memory with 133MHz multi I/O SPI & quad I/O QPI DTR
// interface" data sheet, https://www.issi.com/WW/pdf/IS25LP128.pdf (IS25WP128 is its 1.8 V twin).
// The revision could not be checked here: the features page of the preliminary Rev. A (5/03/2014) and
// of the later 96-page data sheet were read (the two agree on the rows marked "features" below); the
// other rows come from third-party code quoting the data sheet, or are assumed. Every number is a
// SpiFlashConfig field, so a board with another part (the IS25LP128F: 80 MHz normal read, 166 MHz
// fast read, same JEDEC ID; or a 32 MiB part) sets its own.
//
//   value                     IS25LP128          where it comes from
//   READ 0x03 SCK max (fC)    50 MHz             features page ("50MHz Normal Read")            verified
//   other SCK max (fCT)       133 MHz            features page ("133Mhz Fast Read at Vcc=2.7V to
//                                                3.6V"; 104 MHz from 2.3 V; the ULX3S runs 3.3 V) verified
//   SPI modes                 0 and 3            features page                                  verified
//   page / sector             256 B / 4 KiB      features page                                  verified
//   SECTOR ERASE opcodes      0x20 and 0xD7      a write-up reading the data sheet              secondary
//   JEDEC ID (0x9F)           9D 60 18           drivers for the part (flashrom, several)       secondary
//   tCEH CS# high time        7 ns               a driver's comment quoting the data sheet      secondary
//   tCS  CS# setup to SCK     6 ns               same comment                                   secondary
//   tCH  CS# hold after SCK   6 ns               same comment                                   secondary
//   tPP  page program         0.2 ms typical     (an IS25LP128F driver quotes 0.8 ms max)       ASSUMED
//   tSE  sector erase         70 ms typical      an IS25LP128F driver quotes 70..300 ms         secondary
//   tDP  CS# high to DPD      3 us                                                              ASSUMED
//   tRES1 release to standby  3 us                                                              ASSUMED
//   tRST software reset       100 us (on the safe side)                                         ASSUMED
//   RES electronic ID (0xAB)  0x17                                                              ASSUMED
//   FAST READ dummy clocks    8 (the power-up default)                                          ASSUMED
// Busy times are typical figures: a controller that polls WIP works with any, one that waits a fixed
// time should be checked with the maximum (set tPP_ps / tSE_ps).
//
// Calling convention. step(t_ps, cs_n, sck, mosi) gives the levels of the pins from time t_ps on
// (picoseconds; t_ps never decreases — a decrease throws std::invalid_argument; equal times are fine).
// The model compares them with the previous call's levels and acts on the edges between:
//   - CS# falling: a command begins. SCK's level just before (the previous call's) picks the SPI mode:
//     low = mode 0, high = mode 3. The first call counts as a CS# fall when it has CS# low.
//   - SCK rising with CS# low: MOSI (this call's level) is shifted in, MSB first.
//   - SCK falling with CS# low: in an output phase the next bit goes on MISO, valid from this call on
//     (the output delay tV is taken as zero) and held until the next falling edge.
//   - CS# rising: the command ends — WREN, WRDI, PAGE PROGRAM, SECTOR ERASE, DEEP POWER-DOWN,
//     RELEASE and RESET take effect here — and MISO goes High-Z at once (tDIS taken as zero).
//   CS# and SCK changing in the same call are taken in the order CS# fall, SCK edge, CS# rise, so an SCK
//   edge at the very instant CS# moves is seen (and breaks tCS or tCH).
// The return value is MISO and whether the flash drives it (oe; undriven, miso reads 0). MISO changes
// only at falling SCK edges and at CS#, so a master sampling at a rising edge may take the value the
// call for that edge returns or the one before: they are the same.
// Data out: READ 0x03 after 8 + 24 rising edges, FAST READ 0x0B after 8 + 24 + 8, RDID 0x9F and RDSR
// 0x05 after 8, RES (0xAB + 3 dummy bytes) after 32: the first data bit is driven from the falling edge
// after that many rising edges. READ streams on, the address wrapping at the end of the array; RDSR
// repeats the status register, each repetition read afresh (WIP can drop mid-poll); RDID repeats its
// three bytes (what follows them is not in the data sheet: ASSUMED).
//
// What is checked (each violation names the rule — the names are SpiFlashViolation::rule — the time
// and the command; its text ends in "[rule]"):
//   fSCK             an SCK period (rising edge to rising edge, CS# low) shorter than the command allows:
//                    1/fC for READ 0x03, 1/fCT for every other command (the opcode's own clocks count);
//                    once per command
//   tCEH             CS# high for less than tCEH between two commands
//   tCS              CS# falling to the first rising SCK edge less than tCS
//   tCH              the last rising SCK edge to CS# rising less than tCH
//   byte boundary    CS# rising within a byte: in the opcode (any command), or in a PAGE PROGRAM, SECTOR
//                    ERASE, WREN, WRDI, DEEP POWER-DOWN, RESET ENABLE, RESET (the data sheet ignores them)
//   length           the same commands ending on a byte boundary but at the wrong length: SECTOR ERASE
//                    not exactly 4 bytes, the one-byte commands longer than 1, a PAGE PROGRAM without
//                    a data byte; ignored
//   deep power-down  any command but RELEASE 0xAB in deep power-down; ignored
//   tDP              a command less than tDP after DEEP POWER-DOWN (still entering it); ignored unless 0xAB
//   tRES1            a command less than tRES1 after RELEASE left deep power-down; carried out
//   tRST             a command less than tRST after RESET; carried out
//   busy             any command but RDSR while a program or erase runs (WIP); ignored
//   WEL              PAGE PROGRAM or SECTOR ERASE without the write enable latch (no WREN); ignored
//   reset enable     RESET 0x99 not right after RESET ENABLE 0x66; ignored
//   opcode           an opcode this model does not carry (named in the message); the rest ignored
// "Ignored" is what the chip does; "carried out" keeps a simulation going after the report.
//
// Commands: READ 0x03, FAST READ 0x0B, RDID 0x9F, RDSR 0x05 (bit 0 WIP, bit 1 WEL; the protection and
// QE bits read 0 and are not modelled), WREN 0x06, WRDI 0x04, PAGE PROGRAM 0x02 (1 -> 0 bits only; the
// address wraps within the 256-byte page, the last byte sent to a location wins; WIP for tPP, then WIP
// and WEL clear), SECTOR ERASE 0x20 / 0xD7 (4 KiB to 0xFF; WIP for tSE), DEEP POWER-DOWN 0xB9, RELEASE
// 0xAB (and its RES form reading the electronic ID), RESET ENABLE 0x66 / RESET 0x99 (WEL cleared).
// Addresses are 24 bits: a part larger than 16 MiB is reached in its lower 16 MiB only (3-byte mode,
// bank 0), a READ streaming on past 0xFFFFFF goes on into the upper half (ASSUMED).
//
// Not modelled: dual/quad/QPI/DTR commands, block and chip erase, status/function/read register writes
// and block protection, suspend/resume, OTP/SFDP/unique ID, HOLD# and WP#, input setup/hold (tDS, tDH:
// the model sees the pins only at the calls), SCK high/low times, power-up (tVSL), output delays.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

struct SpiFlashConfig {
    uint32_t size_bytes = 16u << 20;                  // a power of two, 64 KiB .. 256 MiB; erased = 0xFF
    std::array<uint8_t, 3> jedec_id{{0x9D, 0x60, 0x18}};  // RDID 0x9F: manufacturer, type, capacity
    uint8_t electronic_id = 0x17;                     // RES (0xAB + 3 dummy bytes): ASSUMED
    uint32_t fast_read_dummy_clocks = 8;              // FAST READ 0x0B between address and data

    uint64_t read_max_hz = 50000000;     // fC: READ 0x03
    uint64_t max_hz = 133000000;         // fCT: every other command (FAST READ, RDID, RDSR, ...)
    uint64_t tCEH_ps = 7000;             // CS# high between commands
    uint64_t tCS_ps = 6000;              // CS# low to the first rising SCK edge
    uint64_t tCH_ps = 6000;              // the last rising SCK edge to CS# high
    uint64_t tDP_ps = 3000000;           // DEEP POWER-DOWN's CS# rise to deep power-down (3 us, ASSUMED)
    uint64_t tRES1_ps = 3000000;         // RELEASE's CS# rise to standby (3 us, ASSUMED)
    uint64_t tRST_ps = 100000000;        // RESET's CS# rise to standby (100 us, ASSUMED)
    uint64_t tPP_ps = 200000000;         // PAGE PROGRAM busy (0.2 ms typical, ASSUMED)
    uint64_t tSE_ps = 70000000000ull;    // SECTOR ERASE busy (70 ms typical)

    bool start_in_deep_power_down = false;  // as after an earlier 0xB9: the first command must be 0xAB
    bool fail_fast = false;                 // the first violation goes to stderr and failed() is true
    uint32_t max_messages = 1000;           // violations kept as text (all are counted)
};

// What the flash drives on SO (MISO).
struct SpiFlashOut {
    bool miso;  // 0 when not driven
    bool oe;    // the flash drives MISO
};

struct SpiFlashViolation {
    uint64_t t_ps;
    std::string rule;     // "fSCK", "tCEH", "busy", ... (the header's list)
    std::string command;  // "READ (0x03) at 0x001000", "opcode 0x3B", "(incomplete opcode)"
    std::string text;     // the whole message, as errors() has it
};

struct SpiFlashCounters {
    std::array<uint64_t, 256> commands{};  // by opcode: every whole opcode received, carried out or not
    uint64_t selections = 0;               // CS# low periods
    uint64_t mode3_selections = 0;         // of which began with SCK high (SPI mode 3)
    uint64_t bytes_read = 0;               // READ / FAST READ data bytes clocked out whole
    uint64_t bytes_programmed = 0;         // locations written by PAGE PROGRAM
    uint64_t pages_programmed = 0;
    uint64_t sectors_erased = 0;
    uint64_t min_sck_period_ps = 0;        // the shortest SCK period seen with CS# low (0: none yet)
};

class SpiFlash {
public:
    static constexpr uint32_t kPageBytes = 256;
    static constexpr uint32_t kSectorBytes = 4096;

    // Throws std::invalid_argument for a size that is not a power of two in range, or a zero frequency.
    explicit SpiFlash(const SpiFlashConfig &cfg = SpiFlashConfig());

    // The pins from t_ps on (see the calling convention above); returns what the flash drives.
    SpiFlashOut step(uint64_t t_ps, bool cs_n, bool sck, bool mosi);

    // Backdoor, no timing and no checks: load overwrites (it is not a program: 0 -> 1 works), e.g. a
    // firmware image at its offset. Out of range throws std::out_of_range; load_file returns false and
    // says why in *error.
    void load(uint32_t offset, const uint8_t *data, size_t n);
    void load(uint32_t offset, const std::vector<uint8_t> &bytes) { load(offset, bytes.data(), bytes.size()); }
    bool load_file(uint32_t offset, const std::string &path, std::string *error);
    std::vector<uint8_t> read_backdoor(uint32_t offset, size_t n) const;
    uint8_t peek(uint32_t addr) const;  // addr < size

    bool failed() const { return cfg_.fail_fast && error_count_ != 0; }
    const std::vector<std::string> &errors() const { return errors_; }  // "spiflash: <t>: <command>: ... [rule]"
    const std::vector<SpiFlashViolation> &violations() const { return violations_; }
    uint64_t error_count() const { return error_count_; }                // all, kept or not
    std::string describe() const;  // the first violation's text, or "no violations"
    const SpiFlashCounters &counters() const { return counters_; }
    std::string stats() const;     // one line: commands by name, bytes read/programmed, sectors, violations

    bool read_in_progress() const;  // a READ / FAST READ is streaming data now
    bool busy() const { return busy_; }                    // WIP, as of the last step
    bool write_enabled() const { return wel_; }            // WEL, as of the last step
    bool deep_power_down() const { return power_down_; }
    uint8_t status() const { return static_cast<uint8_t>((busy_ ? 1 : 0) | (wel_ ? 2 : 0)); }  // RDSR's byte
    const SpiFlashConfig &config() const { return cfg_; }

    static std::string command_name(uint8_t opcode);  // "READ (0x03)", ..., "opcode 0x3B"

private:
    enum class Phase : uint8_t {
        kIdle,     // CS# high
        kOpcode,   // the first 8 bits
        kAddress,  // 24 address bits (24 dummy bits for RES)
        kDummy,    // FAST READ's dummy clocks
        kOutput,   // data on MISO
        kProgram,  // PAGE PROGRAM's data bytes
        kTail,     // nothing more expected (bits are counted for the length check)
        kIgnore,   // the command is ignored: the rest of the selection too
    };

    static std::string time_text(uint64_t ps);
    void violation(uint64_t t, const char *rule, const std::string &what);
    std::string command_text() const;  // the current command with its address when it has one
    bool has_address() const;

    void begin_selection(uint64_t t, bool sck_before);
    void end_selection(uint64_t t);
    void on_rise(uint64_t t, bool mosi);
    void on_fall();
    void decode(uint64_t t);
    void selection_checks(uint64_t t);
    void check_period(uint64_t period, uint64_t t);
    void address_done();
    uint8_t next_output_byte();
    bool exact_length(uint32_t bytes);
    void execute(uint64_t t, bool reset_armed);
    void start_busy(uint64_t t, uint64_t duration, const std::string &what);

    uint8_t read_byte(uint32_t addr) const;
    void write_byte(uint32_t addr, uint8_t v);

    SpiFlashConfig cfg_;
    uint32_t mask_;                        // size - 1
    uint64_t read_min_period_ps_;          // ceil(1e12 / read_max_hz)
    uint64_t min_period_ps_;               // ceil(1e12 / max_hz)
    std::vector<std::vector<uint8_t>> sectors_;  // empty = erased (all 0xFF)

    // The pins as of the last call.
    bool started_ = false;
    uint64_t t_ = 0;
    bool cs_n_ = true, sck_ = false;
    bool miso_ = false, oe_ = false;

    // Device state.
    bool wel_ = false;
    bool busy_ = false;
    uint64_t busy_until_ = 0;              // WIP until here (program / erase)
    std::string busy_what_;
    bool power_down_ = false;
    uint64_t power_down_from_ = 0;         // DEEP POWER-DOWN's CS# rise
    uint64_t power_down_at_ = 0;           // deep power-down reached here (tDP after 0xB9)
    uint64_t ready_from_ = 0;              // RELEASE's / RESET's CS# rise
    uint64_t ready_at_ = 0;                // standby from here on
    const char *ready_rule_ = "tRES1";
    std::string ready_after_;              // the command that started the wait
    bool reset_enabled_ = false;           // the last command was RESET ENABLE
    bool cs_rose_ = false;                 // a CS# rise was seen (tCEH counts from it)
    uint64_t cs_rise_t_ = 0;
    std::string last_command_;

    // The current selection (CS# low).
    Phase phase_ = Phase::kIdle;
    uint64_t sel_t_ = 0;                   // CS# fell here
    uint32_t rises_ = 0;                   // rising SCK edges since CS# fell
    uint64_t first_rise_t_ = 0, last_rise_t_ = 0;
    uint64_t sel_min_period_ = 0;          // the shortest SCK period in this selection (0: none)
    bool decoded_ = false;
    bool ignored_ = false;
    bool fsck_reported_ = false;
    uint8_t opcode_ = 0;
    uint32_t shift_ = 0;                   // bits shifted in, the opcode's or a data byte's
    uint32_t field_ = 0;                   // bits in the current phase
    uint32_t addr_ = 0;                    // the address counter
    uint32_t cmd_addr_ = 0;                // the command's address, as sent (masked to the array)
    bool addr_done_ = false;
    uint32_t out_index_ = 0;               // bytes fetched for output (RDID's byte index)
    uint8_t out_byte_ = 0;
    uint32_t out_bit_ = 0;                 // the next bit of out_byte_ to drive, 0 = MSB
    std::array<uint8_t, kPageBytes> page_{};
    std::array<bool, kPageBytes> page_set_{};
    uint32_t page_bytes_in_ = 0;           // data bytes received by PAGE PROGRAM

    std::vector<std::string> errors_;
    std::vector<SpiFlashViolation> violations_;
    uint64_t error_count_ = 0;
    SpiFlashCounters counters_;
};
