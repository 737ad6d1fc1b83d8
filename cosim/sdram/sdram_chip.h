// SdramChip: a cycle-level model of the ULX3S's SDR SDRAM, ISSI IS42S16160G (32 MB, x16: 4 banks x
// 8,192 rows x 512 columns x 16 bits), at the chip's pins, for the Verilator benches (the controller
// under test drives the pins; this model answers on DQ and checks every command against the data
// sheet). C++17, no Verilator dependency.
//
// Source: ISSI "IS42S83200G, IS42S16160G / IS45S83200G, IS45S16160G — 32Meg x 8, 16Meg x16 256Mb
// Synchronous DRAM", Rev. F, 12/9/2013: the command and functional truth tables (pp. 9-13), AC
// electrical characteristics (p. 18), operating frequency / latency relationships (p. 19),
// initialization (pp. 21-22), mode register and burst order (pp. 25-27), read and write bursts
// (pp. 29, 39), concurrent auto precharge (p. 50). Default speed grade: -7 (IS42S16160G-7TL, the part
// on ULX3S v3.1 boards; 143 MHz at CL 3, 133 MHz at CL 2), commercial/industrial temperature (8,192
// refreshes per 64 ms). SdramConfig::speed_grade(5 | 6 | 7) gives the others; -7 is not the slowest
// in every parameter (-6 needs tRCD and tRP of 18 ns), so a controller meant for any grade should
// pass speed_grade(6) too. Only the data sheet's facts are carried over; the model shares nothing
// with the controller it checks.
//
//                       -5       -6       -7     (ns unless said)
//   tCK  CL3 / CL2      5 / 10   6 / 10   7 / 7.5
//   tRC  (= tRFC)       60       60       60      ACT->ACT same bank, REF->REF/ACT
//   tRAS min / max      45/100K  42/100K  37/100K ACT->PRE
//   tRP                 15       18       15      PRE->ACT/REF/LMR
//   tRCD                15       18       15      ACT->READ/WRITE
//   tRRD                10       12       14      ACT->ACT other bank
//   tDPL (tWR)          10       12       14      last data in -> PRE
//   tDAL                25       30       30      last data in -> ACT/REF, write with auto precharge
//   tMRD                2 clocks (10/12/14 ns, never more than 2 clocks at a legal tCK)
//   tREF                64 ms for 8,192 AUTO REFRESH (tREFI = 7.8125 us)
//   power-up wait       100 us of NOP / COMMAND INHIBIT with CKE high before the first command
//                       (p. 21 says 100 us twice and the figure "T = 100us Min."; one sentence there
//                       mentions "the 200us period": the model takes 100 us, the firmware waits 200)
//
// Calling convention — zero delay. clock(pins) is called once per rising edge of the chip's clock,
// with the pins as sampled at that edge; edges are numbered from 0 (the first call). The return
// value is what the chip drives on DQ from that edge until the next one, i.e. what a controller
// samples just before the next edge. So:
//   - READ sampled at edge n, CAS latency CL: word k of the burst is the return value of the call for
//     edge n + CL - 1 + k (the data sheet's "valid by edge n + CL + k", p. 27).
//   - WRITE sampled at edge n: word k is taken from dq_in at edge n + k, masked per byte by the DQM of
//     the same edge (DQM write latency 0, tDMD).
//   - DQM on reads: DQM sampled at edge m masks the word the chip would drive from the call for edge
//     m + 1 (valid at edge m + 2: DQM read latency 2, tQMD). A masked byte is not driven (byte_oe).
//   - BURST TERMINATE or PRECHARGE at edge m ends a READ burst's output from the word valid at edge
//     m + CL (tRBD, tRQL = CL); ends a WRITE burst so that the data at edge m is ignored (tWBD, tWDL = 0).
//   - A READ or WRITE truncates the running burst (any bank); a WRITE at edge m also drops every read
//     word still in the pipeline that would be valid after edge m (the DQs go High-Z).
//   - Bus contention: the controller drives DQ (dq_driven) at an edge while the chip's drive from
//     the previous call is on the bus.
//
// What is checked (each violation names the command, the bank/row and the parameter; the parameter
// names are those of SdramViolation::param):
//   power-up       a command before the power-up wait (counted from the first edge with CKE high) is over
//   initialisation the sequence: PRECHARGE of every bank (PRECHARGE ALL), then at least 2 AUTO REFRESH
//                  and a LOAD MODE REGISTER in either order (p. 22 note 2: the mode register may be
//                  loaded before the refreshes); any other command before that is an error
//   reserved, CAS latency, burst length, tCK
//                  the mode register: BA1, BA0, A12..A10 must be 0 (p. 25 note 1), operating mode
//                  M8..M7 = 00, CL 2 or 3, BL 1/2/4/8 or full page (sequential only); the clock period
//                  must be at least the grade's tCK for the programmed CL
//   mode register  READ/WRITE while the mode register holds no valid value
//   bank state     ACTIVE only to an idle bank; READ/WRITE only to an active one; no command to a bank
//                  whose auto-precharge burst is still running (except the end of it); BURST TERMINATE
//                  not on a burst with auto precharge
//   all banks idle AUTO REFRESH and LOAD MODE REGISTER need every bank idle
//   tRCD tRP tRAS "tRAS max" tRC tRFC tRRD tWR tDAL tMRD
//                  as the table above; tWR counts from the last written (DQM-unmasked) data edge of
//                  the bank; tMRD forbids any command but NOP/INHIBIT after LMR, tRFC any but
//                  NOP/INHIBIT/BST after AUTO REFRESH (the functional truth table, p. 13)
//   tREFI, tREF    the refresh budget, from the end of initialisation on (check_refresh):
//                  tREFI: no more than 9 x tREFI (70.3 us) between two AUTO REFRESH — JEDEC's allowance of
//                    up to 8 postponed refreshes; a controller that misses refreshes is caught within
//                    70 us instead of at the end of a 64 ms window;
//                  tREF: every window of 64 ms holds at least 8,192 AUTO REFRESH, checked exactly: the
//                    i-th and (i + 8192)-th refresh (the end of initialisation counting as refresh 0)
//                    are at most 64 ms apart, which catches a controller refreshing a little too slowly,
//                    which the gap rule lets through: tREFI rounded up to whole clocks (391 clocks =
//                    7.82 us at 50 MHz) takes 64.05 ms for 8,192 and is reported 64 ms into the run.
//                  Both are checked at every edge against the next deadline (one compare) and by
//                  finish(), which also reports a row left open longer than tRAS max.
//   bus contention see above; DQ: a WRITE data edge with a byte enabled that the controller does not drive
//   uninitialised  a read of a byte never written: an error when strict_uninitialised_reads, otherwise
//                  counted and answered with uninitialised_value
//   unsupported    CKE low after the power-up sequence began (power-down, self refresh, clock suspend)
//                  is reported, not modelled; so is auto precharge with a full-page burst (the data
//                  sheet does not define when its precharge would start)
//
// Auto precharge (A10 on READ/WRITE): the implied precharge starts at the earliest valid edge (p. 8):
// READ: after the burst's last column (edge n + BL), WRITE: tDPL after its last data edge, and never
// before tRAS min after the ACTIVE; a burst truncated by an access to another bank (concurrent auto
// precharge, p. 50) starts it at that access (READ) or tDPL after it (WRITE). The bank then takes
// ACTIVE/REFRESH after tRP (READ) or tDAL after the last data (WRITE), and never before tRAS + tRP
// after its ACTIVE. A violation names tRP (READ) or tDAL (WRITE).
//
// Not modelled: output and input timing within a clock (tAC, tOH, tLZ, tHZ, setup/hold — the model is
// zero-delay), power-down, self refresh and clock suspend (see "unsupported"), tXSR and tPDE, the x8
// part, the A2 grade's 32 ms refresh above 85 C (set tREF_ps), and data retention: a row that misses
// its refresh keeps its data (the violation is reported instead).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

struct SdramConfig {
    // Geometry (x16): banks, rows and columns are powers of two; the banks fit BA1..BA0, the rows A12..A0.
    uint32_t banks = 4;
    uint32_t rows = 8192;
    uint32_t cols = 512;
    uint64_t clock_period_ps = 20000;  // 50 MHz: the board's SDRAM clock

    // Timing of the -7 grade (see the table above), in picoseconds unless named otherwise.
    uint64_t tCK_cl2_ps = 7500;        // the shortest clock period at CAS latency 2
    uint64_t tCK_cl3_ps = 7000;        // ... at CAS latency 3
    uint64_t tRCD_ps = 15000;
    uint64_t tRP_ps = 15000;
    uint64_t tRAS_ps = 37000;
    uint64_t tRAS_max_ps = 100000000;  // 100K ns
    uint64_t tRC_ps = 60000;
    uint64_t tRFC_ps = 60000;          // AUTO REFRESH period: tRC on this chip
    uint64_t tWR_ps = 14000;           // the data sheet's tDPL
    uint64_t tDAL_ps = 30000;
    uint64_t tRRD_ps = 14000;
    uint32_t tMRD_clocks = 2;
    uint64_t tREF_ps = 64000000000;    // 64 ms ...
    uint32_t refresh_count = 8192;     // ... for this many AUTO REFRESH
    uint32_t refresh_postpone = 8;     // JEDEC: up to 8 refreshes may be postponed
    uint64_t power_up_ps = 100000000;  // 100 us
    uint32_t init_refreshes = 2;       // AUTO REFRESH in the power-up sequence

    // Knobs.
    bool strict_uninitialised_reads = false;  // a read of a never-written byte is an error
    uint16_t uninitialised_value = 0xDEAD;    // what such a read returns otherwise
    bool check_refresh = true;                // the tREFI / tREF budget (off for benches of a few us)
    bool fail_fast = false;                   // the first violation goes to stderr and failed() is true
    // A fault of the board, not of the chip: address pin A<n> stuck low (-1: none) — every command
    // sees the pin at 0, so rows (or columns) that differ only in it alias. For the tests that show
    // the firmware's memory test catches a broken address line (socsim --sdram-fault-a).
    int stuck_low_address_pin = -1;
    uint32_t max_messages = 10000;            // violations kept as text (all are counted)

    // The data sheet's values for speed grade -5, -6 or -7 (throws std::invalid_argument otherwise),
    // at the default clock.
    static SdramConfig speed_grade(int grade);
};

// What the controller drives, as sampled at the chip's rising clock edge.
struct SdramPins {
    bool cke = false;
    bool cs_n = true;
    bool ras_n = true;
    bool cas_n = true;
    bool we_n = true;
    uint8_t ba = 0;          // BA1..BA0
    uint16_t a = 0;          // A12..A0
    uint8_t dqm = 0;         // bit 0: DQML (DQ7..0), bit 1: DQMH (DQ15..8)
    uint16_t dq_in = 0;      // the value on the DQ bus
    bool dq_driven = false;  // the controller drives DQ at this edge
};

// What the chip drives on DQ from this edge until the next.
struct SdramDrive {
    uint16_t dq;      // bytes not driven read 0
    bool oe;          // any byte driven
    uint8_t byte_oe;  // bit 0: DQ7..0, bit 1: DQ15..8 (a byte masked by DQM is not driven)
};

enum class SdramCommand : uint8_t {
    kInhibit,         // CS high (DESL)
    kNop,
    kActive,
    kRead,
    kReadAp,          // READ with auto precharge
    kWrite,
    kWriteAp,
    kPrecharge,       // one bank
    kPrechargeAll,
    kRefresh,         // AUTO REFRESH
    kSelfRefresh,     // REFRESH with CKE low: unsupported
    kLoadMode,
    kBurstTerminate,
    kCount
};

struct SdramViolation {
    uint64_t edge;
    std::string param;  // "tRCD", "bank state", "tREFI", ... (the header's list)
    std::string text;   // the whole message, as errors() has it
};

struct SdramCounters {
    std::array<uint64_t, static_cast<size_t>(SdramCommand::kCount)> commands{};  // by SdramCommand
    uint64_t refreshes = 0;             // AUTO REFRESH after initialisation
    uint64_t words_read = 0;            // words driven on DQ (any byte)
    uint64_t words_written = 0;         // words written (any byte)
    uint64_t uninitialised_reads = 0;   // words driven with a byte never written
    uint64_t row_hits = 0;              // READ/WRITE to a row already accessed since its ACTIVE
    uint64_t row_misses = 0;            // the first READ/WRITE after an ACTIVE
    uint64_t longest_refresh_gap_ps = 0;
    uint64_t pages = 0;                 // rows holding written data (cols words each)
};

class SdramChip {
public:
    explicit SdramChip(const SdramConfig &cfg = SdramConfig());

    // One rising edge: the pins as sampled there; returns the chip's drive until the next edge.
    SdramDrive clock(const SdramPins &pins);

    // The end of the run at edge `edge` (default: the edge after the last one clocked): reports an
    // owed refresh and a row left open past tRAS max. Calling it again for the same or an earlier
    // edge does nothing.
    void finish();
    void finish(uint64_t edge);

    bool failed() const { return cfg_.fail_fast && error_count_ != 0; }
    const std::vector<std::string> &errors() const { return errors_; }         // "sdram: edge N (t): ..."
    const std::vector<SdramViolation> &violations() const { return violations_; }
    uint64_t error_count() const { return error_count_; }                      // all, kept or not
    const SdramCounters &counters() const { return counters_; }
    std::string stats() const;  // one line: commands, refreshes, words, pages, violations

    const SdramConfig &config() const { return cfg_; }
    uint64_t edges() const { return static_cast<uint64_t>(edge_); }  // clocked so far = the next edge's number
    bool initialised() const { return init_done_; }
    int cas_latency() const { return mode_.cas_latency; }
    uint32_t burst_length() const { return mode_.burst_length; }  // cols for a full page

    // Backdoor access for tests and loaders (no timing, no checks). peek returns false for a word
    // with a byte never written (that byte then reads as uninitialised_value's).
    bool peek(uint32_t bank, uint32_t row, uint32_t col, uint16_t *value) const;
    void poke(uint32_t bank, uint32_t row, uint32_t col, uint16_t value);

    static const char *command_name(SdramCommand c);

private:
    static constexpr int64_t kNever = INT64_MIN / 4;  // "no such edge yet", safe to subtract from
    static constexpr uint32_t kPipeMask = 7;         // the read pipeline's ring (CL <= 3 words in flight)

    enum class Closed : uint8_t { kNever, kPrecharge, kReadAp, kWriteAp };  // how the bank last closed

    struct Bank {
        bool open = false;                // a row is open and takes READ/WRITE
        uint32_t row = 0;
        int64_t act_edge = kNever;        // the last ACTIVE
        Closed closed = Closed::kNever;
        int64_t busy_edge = kNever;       // its auto-precharge burst runs before this edge
        int64_t pre_edge = kNever;        // the precharge starts here (explicit or implied)
        int64_t ready_edge = kNever;      // from here on ACTIVE/REFRESH/LMR may address the bank
        int64_t ap_edge = kNever;         // the READ/WRITE with auto precharge that closed it
        int64_t ap_ref_edge = kNever;     // what its ready_edge counts from (last data, for a WRITE)
        int64_t last_write_edge = kNever; // the last data edge written (a byte enabled) since ACTIVE
        bool accessed = false;            // a READ/WRITE since ACTIVE (row hit/miss)
        bool tras_max_reported = false;
    };

    struct Burst {
        bool active = false;
        bool write = false;
        bool auto_precharge = false;
        bool full_page = false;           // runs until truncated, wrapping within the row
        bool interleaved = false;
        uint32_t bank = 0, row = 0, start_col = 0;
        uint32_t length = 1;              // words (cols for a full page)
        uint32_t index = 0;               // the next word
        int cas_latency = 2;
        int64_t start_edge = 0;
    };

    struct OutWord {                      // a read word in the CAS-latency pipeline
        int64_t valid_edge;               // valid at this edge: driven by the call for the edge before
        uint16_t data;
        uint8_t written;                  // bytes ever written
        uint32_t bank, row, col;
    };

    struct Page {                         // one row, allocated at its first write
        std::vector<uint16_t> data;
        std::vector<uint8_t> written;     // per word: bit 0 low byte, bit 1 high byte
    };

    struct Mode {
        uint32_t burst_length = 1;        // cols for a full page
        bool full_page = false;
        bool interleaved = false;
        int cas_latency = 0;              // 0 until a valid LOAD MODE REGISTER
        bool single_write = false;        // M9: WRITE bursts of one
    };

    int64_t clocks(uint64_t ps) const;    // the whole clocks that cover ps
    uint64_t refresh_gap_ps() const;      // (postponed + 1) x tREFI
    std::string time_text(uint64_t ps) const;
    std::string when(int64_t edge) const;  // "edge N (t)"
    void violation(int64_t edge, const char *param, const std::string &what);
    void timing(int64_t edge, const std::string &cmd, int64_t since, const std::string &since_what,
                const char *param, uint64_t t_ps, int64_t need);

    SdramCommand decode(const SdramPins &p) const;
    std::string describe(SdramCommand c, const SdramPins &p) const;
    void execute(SdramCommand c, const SdramPins &p);
    void init_gate(SdramCommand c, const std::string &name);
    void check_guards(SdramCommand c, const std::string &name);
    bool check_ready(uint32_t b, const std::string &cmd, const char *state_param);
    bool check_all_idle(const std::string &name);
    void cmd_active(uint32_t b, uint32_t row, const std::string &name);
    void cmd_access(uint32_t b, uint32_t col, bool write, bool ap, const std::string &name);
    void cmd_precharge(uint32_t b, bool all, const std::string &name);
    void cmd_refresh(const std::string &name);
    void cmd_load_mode(uint8_t ba, uint16_t a, const std::string &name);
    void cmd_burst_terminate(const std::string &name);
    void close_auto_precharge(uint32_t b, bool write, int64_t start, int64_t end, bool truncated);
    void end_burst(int64_t edge);
    void step_burst(const SdramPins &p);
    SdramDrive drive_out();
    uint64_t window_start() const;
    void set_refresh_deadline();
    void refresh_overdue(int64_t edge, bool at_finish);
    uint32_t burst_col(const Burst &b, uint32_t k) const;
    Page &page(uint32_t bank, uint32_t row);
    const Page *find_page(uint32_t bank, uint32_t row) const;

    SdramConfig cfg_;
    int64_t edge_ = 0;
    // The data sheet's times in whole clocks of this clock.
    int64_t c_rcd_, c_rp_, c_ras_, c_ras_rp_, c_rc_, c_rfc_, c_wr_, c_dal_, c_rrd_, c_mrd_, c_power_up_;
    int64_t c_refresh_gap_, c_refresh_window_;  // the latest edge offsets a refresh may come at
    uint32_t col_mask_;

    // Power-up and initialisation.
    int64_t power_start_edge_ = -1;  // the first edge with CKE high
    bool nop_seen_ = false;
    bool init_started_ = false;      // a command other than NOP/INHIBIT was registered
    uint32_t precharged_mask_ = 0;
    uint32_t init_refreshes_ = 0;
    bool mode_loaded_ = false;
    bool init_done_ = false;
    bool cke_low_reported_ = false;

    std::vector<Bank> banks_;
    Burst burst_;
    Mode mode_;
    bool mode_ok_ = false;
    int64_t lmr_edge_ = kNever;
    int64_t refresh_edge_ = kNever;  // the last AUTO REFRESH (any), for tRFC
    int64_t finished_edge_ = -1;

    std::array<OutWord, kPipeMask + 1> pipe_{};
    uint32_t pipe_head_ = 0, pipe_count_ = 0;
    uint8_t dqm_prev_ = 0;           // DQM sampled at the previous edge
    SdramDrive last_drive_{0, false, 0};
    OutWord driven_{};               // the word last driven (for the contention message)

    // The refresh budget, from the end of initialisation (refresh 0) on.
    std::vector<int64_t> refresh_ring_;  // the edge of refresh i at i % refresh_count
    uint64_t refresh_n_ = 0;
    int64_t refresh_last_ = 0;
    int64_t refresh_deadline_ = 0;       // the next refresh is due by this edge
    bool refresh_deadline_is_window_ = false;
    bool refresh_reported_ = false;

    std::unordered_map<uint32_t, Page> pages_;  // bank * rows + row

    std::vector<std::string> errors_;
    std::vector<SdramViolation> violations_;
    uint64_t error_count_ = 0;
    SdramCounters counters_;
};
