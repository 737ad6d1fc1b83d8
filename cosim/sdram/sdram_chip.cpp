// SdramChip: see sdram_chip.h. Written from the ISSI IS42S16160G data sheet (Rev. F) alone: the
// command decode is its command truth table, the per-bank rules its functional truth table.
#include "sdram_chip.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

namespace {

constexpr size_t kCommandKinds = static_cast<size_t>(SdramCommand::kCount);

bool power_of_two(uint64_t v) { return v != 0 && (v & (v - 1)) == 0; }

std::string clocks_text(int64_t n) { return std::to_string(n) + (n == 1 ? " clock" : " clocks"); }

std::string hex(uint32_t v, int digits) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "0x%0*x", digits, v);
    return buf;
}

const char *const kShortName[kCommandKinds] = {"DESL", "NOP", "ACT", "RD", "RDA", "WR", "WRA",
                                               "PRE", "PREA", "REF", "SREF", "LMR", "BST"};

}  // namespace

SdramConfig SdramConfig::speed_grade(int grade) {
    SdramConfig c;  // -7
    switch (grade) {
    case 5:
        c.tCK_cl2_ps = 10000;
        c.tCK_cl3_ps = 5000;
        c.tRAS_ps = 45000;
        c.tRP_ps = 15000;
        c.tRCD_ps = 15000;
        c.tRRD_ps = 10000;
        c.tWR_ps = 10000;
        c.tDAL_ps = 25000;
        break;
    case 6:
        c.tCK_cl2_ps = 10000;
        c.tCK_cl3_ps = 6000;
        c.tRAS_ps = 42000;
        c.tRP_ps = 18000;
        c.tRCD_ps = 18000;
        c.tRRD_ps = 12000;
        c.tWR_ps = 12000;
        c.tDAL_ps = 30000;
        break;
    case 7:
        break;
    default:
        throw std::invalid_argument("SdramConfig::speed_grade: the IS42S16160G comes in -5, -6 and -7");
    }
    return c;
}

SdramChip::SdramChip(const SdramConfig &cfg) : cfg_(cfg) {
    if (!power_of_two(cfg_.banks) || cfg_.banks > 4 || !power_of_two(cfg_.rows) || cfg_.rows > 8192 ||
        !power_of_two(cfg_.cols) || cfg_.cols > 1024 || cfg_.clock_period_ps == 0 || cfg_.refresh_count == 0) {
        throw std::invalid_argument("SdramConfig: banks <= 4, rows <= 8192, cols <= 1024 (powers of two), a clock period "
                                    "and a refresh count are needed");
    }
    c_rcd_ = clocks(cfg_.tRCD_ps);
    c_rp_ = clocks(cfg_.tRP_ps);
    c_ras_ = clocks(cfg_.tRAS_ps);
    c_ras_rp_ = clocks(cfg_.tRAS_ps + cfg_.tRP_ps);
    c_rc_ = clocks(cfg_.tRC_ps);
    c_rfc_ = clocks(cfg_.tRFC_ps);
    c_wr_ = clocks(cfg_.tWR_ps);
    c_dal_ = clocks(cfg_.tDAL_ps);
    c_rrd_ = clocks(cfg_.tRRD_ps);
    c_mrd_ = cfg_.tMRD_clocks;
    c_power_up_ = clocks(cfg_.power_up_ps);
    // The latest edges a refresh may come at: whole clocks within the allowance.
    c_refresh_gap_ = static_cast<int64_t>(refresh_gap_ps() / cfg_.clock_period_ps);
    c_refresh_window_ = static_cast<int64_t>(cfg_.tREF_ps / cfg_.clock_period_ps);
    col_mask_ = cfg_.cols - 1;
    banks_.resize(cfg_.banks);
    refresh_ring_.assign(cfg_.refresh_count, 0);
}

int64_t SdramChip::clocks(uint64_t ps) const {
    return static_cast<int64_t>((ps + cfg_.clock_period_ps - 1) / cfg_.clock_period_ps);
}

uint64_t SdramChip::refresh_gap_ps() const {
    return cfg_.tREF_ps * (cfg_.refresh_postpone + 1ull) / cfg_.refresh_count;
}

std::string SdramChip::time_text(uint64_t ps) const {
    double v;
    const char *unit;
    if (ps < 1000000ull) {
        v = static_cast<double>(ps) / 1e3;
        unit = "ns";
    } else if (ps < 1000000000ull) {
        v = static_cast<double>(ps) / 1e6;
        unit = "us";
    } else {
        v = static_cast<double>(ps) / 1e9;
        unit = "ms";
    }
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.2f", v);
    std::string s = buf;
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
    return s + " " + unit;
}

std::string SdramChip::when(int64_t edge) const {
    return "edge " + std::to_string(edge) + " (" + time_text(static_cast<uint64_t>(edge) * cfg_.clock_period_ps) + ")";
}

void SdramChip::violation(int64_t edge, const char *param, const std::string &what) {
    ++error_count_;
    const std::string text = "sdram: " + when(edge) + ": " + what;
    if (cfg_.fail_fast && error_count_ == 1) std::fprintf(stderr, "%s\n", text.c_str());
    if (errors_.size() < cfg_.max_messages) {
        errors_.push_back(text);
        violations_.push_back({static_cast<uint64_t>(edge), param, text});
    }
}

// "<cmd> at N clocks after <since_what>: <param> <t> needs M clocks"
void SdramChip::timing(int64_t edge, const std::string &cmd, int64_t since, const std::string &since_what,
                       const char *param, uint64_t t_ps, int64_t need) {
    std::string what = cmd + " at " + clocks_text(edge - since) + " after " + since_what + ": " + param;
    if (t_ps != 0) what += " " + time_text(t_ps);
    violation(edge, param, what + " needs " + clocks_text(need));
}

const char *SdramChip::command_name(SdramCommand c) {
    switch (c) {
    case SdramCommand::kInhibit: return "COMMAND INHIBIT";
    case SdramCommand::kNop: return "NOP";
    case SdramCommand::kActive: return "ACTIVE";
    case SdramCommand::kRead: return "READ";
    case SdramCommand::kReadAp: return "READ with auto precharge";
    case SdramCommand::kWrite: return "WRITE";
    case SdramCommand::kWriteAp: return "WRITE with auto precharge";
    case SdramCommand::kPrecharge: return "PRECHARGE";
    case SdramCommand::kPrechargeAll: return "PRECHARGE ALL";
    case SdramCommand::kRefresh: return "AUTO REFRESH";
    case SdramCommand::kSelfRefresh: return "SELF REFRESH";
    case SdramCommand::kLoadMode: return "LOAD MODE REGISTER";
    case SdramCommand::kBurstTerminate: return "BURST TERMINATE";
    case SdramCommand::kCount: break;
    }
    return "?";
}

// The command truth table (p. 9): CS, RAS, CAS, WE; A10 picks auto precharge / all banks.
SdramCommand SdramChip::decode(const SdramPins &p) const {
    if (p.cs_n) return SdramCommand::kInhibit;
    const bool a10 = (p.a >> 10) & 1;
    switch ((p.ras_n ? 4 : 0) | (p.cas_n ? 2 : 0) | (p.we_n ? 1 : 0)) {
    case 7: return SdramCommand::kNop;
    case 6: return SdramCommand::kBurstTerminate;
    case 5: return a10 ? SdramCommand::kReadAp : SdramCommand::kRead;
    case 4: return a10 ? SdramCommand::kWriteAp : SdramCommand::kWrite;
    case 3: return SdramCommand::kActive;
    case 2: return a10 ? SdramCommand::kPrechargeAll : SdramCommand::kPrecharge;
    case 1: return p.cke ? SdramCommand::kRefresh : SdramCommand::kSelfRefresh;
    default: return SdramCommand::kLoadMode;
    }
}

std::string SdramChip::describe(SdramCommand c, const SdramPins &p) const {
    const uint32_t b = p.ba & (cfg_.banks - 1);
    const Bank &k = banks_[b];
    const std::string bank = " bank " + std::to_string(b);
    const std::string open_row = k.open ? " row " + std::to_string(k.row) : "";
    switch (c) {
    case SdramCommand::kActive:
        return "ACTIVE" + bank + " row " + std::to_string(p.a & (cfg_.rows - 1));
    case SdramCommand::kRead:
    case SdramCommand::kReadAp:
    case SdramCommand::kWrite:
    case SdramCommand::kWriteAp:
        return command_name(c) + bank + open_row + " column " + std::to_string(p.a & col_mask_);
    case SdramCommand::kPrecharge:
        return "PRECHARGE" + bank + open_row;
    case SdramCommand::kLoadMode:
        return "LOAD MODE REGISTER " + hex(p.a, 4) + (p.ba ? " (BA " + std::to_string(p.ba) + ")" : "");
    default:
        return command_name(c);
    }
}

SdramDrive SdramChip::clock(const SdramPins &pins) {
    SdramPins p = pins;
    if (cfg_.stuck_low_address_pin >= 0) {
        p.a &= static_cast<uint16_t>(~(1u << cfg_.stuck_low_address_pin));
    }
    const int64_t e = edge_;
    if (p.dq_driven && last_drive_.oe) {
        violation(e, "bus contention",
                  "bus contention: the controller drives DQ while the chip drives the READ data of bank " +
                      std::to_string(driven_.bank) + " row " + std::to_string(driven_.row) + " column " +
                      std::to_string(driven_.col) + " (valid at this edge)");
    }
    if (init_done_ && cfg_.check_refresh && !refresh_reported_ && e > refresh_deadline_) {
        refresh_overdue(e, false);
    }

    SdramCommand c = decode(p);
    if (!p.cke) {
        if (!init_started_) {
            power_start_edge_ = -1;  // the power-up wait counts from CKE high
            nop_seen_ = false;
        } else if (!cke_low_reported_) {
            cke_low_reported_ = true;
            violation(e, "unsupported",
                      c == SdramCommand::kSelfRefresh
                          ? "SELF REFRESH (CKE low): unsupported by the model"
                          : "CKE low (power-down or clock suspend): unsupported by the model; commands are ignored "
                            "while it is low");
        }
        if (c != SdramCommand::kSelfRefresh) c = SdramCommand::kInhibit;
        ++counters_.commands[static_cast<size_t>(c)];
    } else {
        cke_low_reported_ = false;
        if (power_start_edge_ < 0) power_start_edge_ = e;
        ++counters_.commands[static_cast<size_t>(c)];
        if (c == SdramCommand::kInhibit || c == SdramCommand::kNop) {
            nop_seen_ = true;
        } else {
            execute(c, p);
        }
    }

    step_burst(p);
    const SdramDrive d = drive_out();
    dqm_prev_ = p.dqm & 3;
    last_drive_ = d;
    ++edge_;
    return d;
}

void SdramChip::execute(SdramCommand c, const SdramPins &p) {
    const int64_t e = edge_;
    const uint32_t b = p.ba & (cfg_.banks - 1);
    const std::string name = describe(c, p);
    if (!init_done_) init_gate(c, name);
    check_guards(c, name);
    switch (c) {
    case SdramCommand::kActive:
        cmd_active(b, p.a & (cfg_.rows - 1), name);
        break;
    case SdramCommand::kRead:
    case SdramCommand::kReadAp:
    case SdramCommand::kWrite:
    case SdramCommand::kWriteAp:
        cmd_access(b, p.a & col_mask_, c == SdramCommand::kWrite || c == SdramCommand::kWriteAp,
                   c == SdramCommand::kReadAp || c == SdramCommand::kWriteAp, name);
        break;
    case SdramCommand::kPrecharge:
    case SdramCommand::kPrechargeAll:
        cmd_precharge(b, c == SdramCommand::kPrechargeAll, name);
        break;
    case SdramCommand::kRefresh:
        cmd_refresh(name);
        break;
    case SdramCommand::kLoadMode:
        cmd_load_mode(p.ba, p.a, name);
        break;
    case SdramCommand::kBurstTerminate:
        cmd_burst_terminate(name);
        break;
    default:
        break;
    }
    if (!init_done_) {
        const uint32_t all = (1u << cfg_.banks) - 1;
        if (c == SdramCommand::kPrecharge) precharged_mask_ |= 1u << b;
        if (c == SdramCommand::kPrechargeAll) precharged_mask_ = all;
        if (precharged_mask_ == all && c == SdramCommand::kRefresh) ++init_refreshes_;
        if (precharged_mask_ == all && c == SdramCommand::kLoadMode) mode_loaded_ = true;
        if (precharged_mask_ == all && init_refreshes_ >= cfg_.init_refreshes && mode_loaded_) {
            init_done_ = true;
            refresh_n_ = 0;
            refresh_ring_[0] = e;  // the end of initialisation counts as refresh 0
            refresh_last_ = e;
            refresh_reported_ = false;
            set_refresh_deadline();
        }
    }
}

// Power-up and initialisation (p. 21): 100 us of NOP/INHIBIT with CKE high, PRECHARGE of all banks,
// 2 AUTO REFRESH and LOAD MODE REGISTER in either order (p. 22 note 2); nothing else before that.
void SdramChip::init_gate(SdramCommand c, const std::string &name) {
    const int64_t e = edge_;
    init_started_ = true;
    if (e - power_start_edge_ < c_power_up_ || !nop_seen_) {
        violation(e, "power-up",
                  name + " at " + time_text(static_cast<uint64_t>(e - power_start_edge_) * cfg_.clock_period_ps) +
                      " after CKE went high: the power-up wait needs " + time_text(cfg_.power_up_ps) +
                      " of NOP or COMMAND INHIBIT before the first command");
        return;
    }
    if (c == SdramCommand::kPrecharge || c == SdramCommand::kPrechargeAll) return;
    if (precharged_mask_ != (1u << cfg_.banks) - 1) {
        violation(e, "initialisation",
                  name + " before every bank was precharged: the power-up sequence is PRECHARGE ALL, then " +
                      std::to_string(cfg_.init_refreshes) +
                      " AUTO REFRESH and LOAD MODE REGISTER (in either order)");
        return;
    }
    if (c == SdramCommand::kRefresh || c == SdramCommand::kLoadMode) return;
    std::string missing;
    if (init_refreshes_ < cfg_.init_refreshes) {
        missing = std::to_string(cfg_.init_refreshes - init_refreshes_) + " more AUTO REFRESH";
    }
    if (!mode_loaded_) missing += std::string(missing.empty() ? "" : " and ") + "LOAD MODE REGISTER";
    violation(e, "initialisation", name + " before initialisation is complete: " + missing + " still missing");
}

// The commands the functional truth table (p. 13) forbids outright for a while: anything but
// NOP/INHIBIT within tMRD of LOAD MODE REGISTER, anything but NOP/INHIBIT/BST within tRFC of AUTO REFRESH.
void SdramChip::check_guards(SdramCommand c, const std::string &name) {
    const int64_t e = edge_;
    if (lmr_edge_ != kNever && e - lmr_edge_ < c_mrd_) {
        timing(e, name, lmr_edge_, "LOAD MODE REGISTER", "tMRD", 0, c_mrd_);
    }
    if (c != SdramCommand::kBurstTerminate && refresh_edge_ != kNever && e - refresh_edge_ < c_rfc_) {
        timing(e, name, refresh_edge_, "AUTO REFRESH", "tRFC", cfg_.tRFC_ps, c_rfc_);
    }
}

// May ACTIVE (or REFRESH/LMR, for all banks) address bank b now? Reports why not: still in its
// auto-precharge burst (state_param), or its precharge not yet done (tRP, tDAL).
bool SdramChip::check_ready(uint32_t b, const std::string &cmd, const char *state_param) {
    const int64_t e = edge_;
    const Bank &k = banks_[b];
    const std::string bank = " bank " + std::to_string(b);
    if (k.closed == Closed::kNever) return true;  // never precharged: the initialisation rules speak
    if (e < k.busy_edge) {
        violation(e, state_param,
                  cmd + ": bank " + std::to_string(b) + " is still in its " +
                      (k.closed == Closed::kWriteAp ? "WRITE" : "READ") + " with auto precharge (" + when(k.ap_edge) +
                      "); its burst ends at edge " + std::to_string(k.busy_edge));
        return false;
    }
    if (e < k.ready_edge) {
        switch (k.closed) {
        case Closed::kPrecharge:
            timing(e, cmd, k.pre_edge, "PRECHARGE of" + bank, "tRP", cfg_.tRP_ps, c_rp_);
            break;
        case Closed::kReadAp:
            timing(e, cmd, k.ap_edge,
                   "READ with auto precharge" + bank + " (its precharge starts at edge " + std::to_string(k.pre_edge) +
                       ")",
                   "tRP", cfg_.tRP_ps, k.ready_edge - k.ap_edge);
            break;
        default:
            timing(e, cmd, k.ap_ref_edge, "the last data of WRITE with auto precharge" + bank, "tDAL", cfg_.tDAL_ps,
                   k.ready_edge - k.ap_ref_edge);
            break;
        }
        return false;
    }
    return true;
}

void SdramChip::cmd_active(uint32_t b, uint32_t row, const std::string &name) {
    const int64_t e = edge_;
    Bank &k = banks_[b];
    if (k.open) {
        violation(e, "bank state",
                  name + ": bank " + std::to_string(b) + " has row " + std::to_string(k.row) + " open (" +
                      when(k.act_edge) + "): ACTIVE needs an idle bank (PRECHARGE first)");
    } else {
        check_ready(b, name, "bank state");
    }
    if (k.act_edge != kNever && e - k.act_edge < c_rc_) {
        timing(e, name, k.act_edge, "the ACTIVE of bank " + std::to_string(b), "tRC", cfg_.tRC_ps, c_rc_);
    }
    int64_t other = kNever;
    uint32_t other_bank = 0;
    for (uint32_t j = 0; j < cfg_.banks; ++j) {
        if (j != b && banks_[j].act_edge > other) {
            other = banks_[j].act_edge;
            other_bank = j;
        }
    }
    if (other != kNever && e - other < c_rrd_) {
        timing(e, name, other, "ACTIVE bank " + std::to_string(other_bank), "tRRD", cfg_.tRRD_ps, c_rrd_);
    }
    if (burst_.active && burst_.bank == b) end_burst(e);
    k.open = true;
    k.row = row;
    k.act_edge = e;
    k.last_write_edge = kNever;
    k.accessed = false;
    k.tras_max_reported = false;
}

void SdramChip::cmd_access(uint32_t b, uint32_t col, bool write, bool ap, const std::string &name) {
    const int64_t e = edge_;
    Bank &k = banks_[b];
    if (!k.open) {
        if (k.closed != Closed::kNever && k.closed != Closed::kPrecharge && e < k.busy_edge) {
            violation(e, "bank state",
                      name + ": bank " + std::to_string(b) + " is in its " +
                          (k.closed == Closed::kWriteAp ? "WRITE" : "READ") + " with auto precharge (" +
                          when(k.ap_edge) + "): no other access to it until it is precharged");
        } else {
            violation(e, "bank state",
                      name + ": bank " + std::to_string(b) + " is idle: " + (write ? "WRITE" : "READ") +
                          " needs an active row (ACTIVE first)");
        }
        return;
    }
    if (!mode_ok_) {
        violation(e, "mode register",
                  name + ": the mode register holds no valid value (a valid LOAD MODE REGISTER first)");
        return;
    }
    if (e - k.act_edge < c_rcd_) timing(e, name, k.act_edge, "ACTIVE", "tRCD", cfg_.tRCD_ps, c_rcd_);
    const bool single = write && mode_.single_write;
    const bool full_page = mode_.full_page && !single;
    if (ap && full_page) {
        violation(e, "unsupported",
                  name + ": auto precharge with a full-page burst: unsupported by the model (the data sheet does not "
                         "say when its precharge starts)");
        ap = false;
    }
    ++(k.accessed ? counters_.row_hits : counters_.row_misses);
    k.accessed = true;

    end_burst(e);  // a READ or WRITE truncates the running burst, in any bank
    if (write) {
        // The DQs go High-Z for the WRITE (p. 29): read words valid after this edge are dropped.
        while (pipe_count_ != 0 && pipe_[(pipe_head_ + pipe_count_ - 1) & kPipeMask].valid_edge > e) --pipe_count_;
    }
    burst_.active = true;
    burst_.write = write;
    burst_.auto_precharge = ap;
    burst_.bank = b;
    burst_.row = k.row;
    burst_.start_col = col;
    burst_.full_page = full_page;
    burst_.length = single ? 1 : (full_page ? cfg_.cols : mode_.burst_length);
    burst_.interleaved = mode_.interleaved;
    burst_.cas_latency = mode_.cas_latency;
    burst_.index = 0;
    burst_.start_edge = e;
    if (ap) close_auto_precharge(b, write, e, e + burst_.length, false);
}

// The bank closes with auto precharge: its burst (from edge `start`) ends before edge `end`, by itself
// or truncated by an access to another bank at `end` (concurrent auto precharge, p. 50).
void SdramChip::close_auto_precharge(uint32_t b, bool write, int64_t start, int64_t end, bool truncated) {
    Bank &k = banks_[b];
    const int64_t tras_lock = k.act_edge + c_ras_;  // the precharge waits for tRAS min
    k.open = false;
    k.ap_edge = start;
    k.busy_edge = end;
    if (write) {
        // tDPL counts from the last data edge, or from the truncating access (p. 50, cases 3 and 4).
        const int64_t ref = truncated ? end : end - 1;
        k.closed = Closed::kWriteAp;
        k.ap_ref_edge = ref;
        k.pre_edge = std::max(ref + c_wr_, tras_lock);
        k.ready_edge = std::max(ref + c_dal_, k.act_edge + c_ras_rp_);
    } else {
        k.closed = Closed::kReadAp;
        k.ap_ref_edge = start;
        k.pre_edge = std::max(end, tras_lock);
        k.ready_edge = std::max(end + c_rp_, k.act_edge + c_ras_rp_);
    }
    if (!k.tras_max_reported &&
        static_cast<uint64_t>(k.pre_edge - k.act_edge) * cfg_.clock_period_ps > cfg_.tRAS_max_ps) {
        k.tras_max_reported = true;
        violation(edge_, "tRAS max",
                  std::string(write ? "WRITE" : "READ") + " with auto precharge bank " + std::to_string(b) + " row " +
                      std::to_string(k.row) + ": the row is open for " +
                      time_text(static_cast<uint64_t>(k.pre_edge - k.act_edge) * cfg_.clock_period_ps) +
                      " (from " + when(k.act_edge) + "): tRAS max " + time_text(cfg_.tRAS_max_ps));
    }
}

void SdramChip::end_burst(int64_t edge) {
    if (!burst_.active) return;
    burst_.active = false;
    if (burst_.auto_precharge) close_auto_precharge(burst_.bank, burst_.write, burst_.start_edge, edge, true);
}

void SdramChip::cmd_precharge(uint32_t b, bool all, const std::string &name) {
    const int64_t e = edge_;
    for (uint32_t j = all ? 0 : b; j < (all ? cfg_.banks : b + 1); ++j) {
        Bank &k = banks_[j];
        const std::string what =
            all ? name + " (bank " + std::to_string(j) + (k.open ? " row " + std::to_string(k.row) : "") + ")" : name;
        if (k.open) {
            if (e - k.act_edge < c_ras_) timing(e, what, k.act_edge, "ACTIVE", "tRAS", cfg_.tRAS_ps, c_ras_);
            const uint64_t open_ps = static_cast<uint64_t>(e - k.act_edge) * cfg_.clock_period_ps;
            if (open_ps > cfg_.tRAS_max_ps && !k.tras_max_reported) {
                violation(e, "tRAS max",
                          what + ": the row was open for " + time_text(open_ps) + " (from " + when(k.act_edge) +
                              "): tRAS max " + time_text(cfg_.tRAS_max_ps));
            }
            if (k.last_write_edge != kNever && e - k.last_write_edge < c_wr_) {
                timing(e, what, k.last_write_edge, "the last data written", "tWR", cfg_.tWR_ps, c_wr_);
            }
            if (burst_.active && burst_.bank == j) end_burst(e);
            k.open = false;
            k.closed = Closed::kPrecharge;
            k.busy_edge = k.pre_edge = e;
            k.ready_edge = e + c_rp_;
        } else if (k.closed != Closed::kNever && k.closed != Closed::kPrecharge && e < k.pre_edge) {
            violation(e, "bank state",
                      what + ": bank " + std::to_string(j) + " is in its " +
                          (k.closed == Closed::kWriteAp ? "WRITE" : "READ") + " with auto precharge (" +
                          when(k.ap_edge) + ") until its precharge starts at edge " + std::to_string(k.pre_edge));
        } else if (k.closed == Closed::kNever) {
            // The banks' state at power-up is unknown: this precharge is what makes the bank idle.
            k.closed = Closed::kPrecharge;
            k.busy_edge = k.pre_edge = e;
            k.ready_edge = e + c_rp_;
        }
        // Otherwise idle or precharging already: a NOP (p. 12).
    }
}

// AUTO REFRESH and LOAD MODE REGISTER need every bank idle and precharged: the first bank that is not.
bool SdramChip::check_all_idle(const std::string &name) {
    for (uint32_t j = 0; j < cfg_.banks; ++j) {
        const Bank &k = banks_[j];
        if (k.open) {
            violation(edge_, "all banks idle",
                      name + ": bank " + std::to_string(j) + " has row " + std::to_string(k.row) + " open (" +
                          when(k.act_edge) + "): it needs all banks idle");
            return false;
        }
        if (!check_ready(j, name, "all banks idle")) return false;
    }
    return true;
}

void SdramChip::cmd_refresh(const std::string &name) {
    const int64_t e = edge_;
    check_all_idle(name);
    refresh_edge_ = e;
    if (init_done_) {
        ++counters_.refreshes;
        const uint64_t gap_ps = static_cast<uint64_t>(e - refresh_last_) * cfg_.clock_period_ps;
        counters_.longest_refresh_gap_ps = std::max(counters_.longest_refresh_gap_ps, gap_ps);
        ++refresh_n_;
        refresh_ring_[refresh_n_ % cfg_.refresh_count] = e;
        refresh_last_ = e;
        refresh_reported_ = false;
        set_refresh_deadline();
    }
}

// The mode register (p. 25): M2..M0 burst length, M3 burst type, M6..M4 CAS latency, M8..M7
// operating mode (00 only), M9 write burst mode; BA1, BA0, A12..A10 reserved (to be 0).
void SdramChip::cmd_load_mode(uint8_t ba, uint16_t a, const std::string &name) {
    const int64_t e = edge_;
    check_all_idle(name);
    lmr_edge_ = e;
    bool ok = true;
    if (ba != 0 || (a >> 10) != 0) {
        violation(e, "reserved", name + ": BA1, BA0 and A12..A10 are reserved and must be 0");
        ok = false;
    }
    const uint32_t op = (a >> 7) & 3;
    if (op != 0) {
        violation(e, "reserved",
                  name + ": operating mode M8..M7 = " + std::to_string(op >> 1) + std::to_string(op & 1) +
                      " is reserved (00: standard operation)");
        ok = false;
    }
    const int cl = (a >> 4) & 7;
    if (cl != 2 && cl != 3) {
        violation(e, "CAS latency",
                  name + ": CAS latency M6..M4 = " + std::to_string(cl) + " is reserved (2 or 3)");
        ok = false;
    } else {
        const uint64_t tck_min = cl == 2 ? cfg_.tCK_cl2_ps : cfg_.tCK_cl3_ps;
        if (cfg_.clock_period_ps < tck_min) {
            violation(e, "tCK",
                      name + ": CAS latency " + std::to_string(cl) + " needs a clock period of at least " +
                          time_text(tck_min) + ", the clock's is " + time_text(cfg_.clock_period_ps));
            ok = false;
        }
    }
    const uint32_t bl = a & 7;
    const bool interleaved = (a >> 3) & 1;
    if (bl >= 4 && bl <= 6) {
        violation(e, "burst length", name + ": burst length M2..M0 = " + std::to_string(bl) + " is reserved");
        ok = false;
    } else if (bl == 7 && interleaved) {
        violation(e, "burst length", name + ": a full-page burst (M2..M0 = 7) must be sequential (M3 = 0)");
        ok = false;
    }
    mode_ok_ = ok;
    if (!ok) return;
    mode_.full_page = bl == 7;
    mode_.burst_length = mode_.full_page ? cfg_.cols : 1u << bl;
    mode_.interleaved = interleaved;
    mode_.cas_latency = cl;
    mode_.single_write = (a >> 9) & 1;
}

void SdramChip::cmd_burst_terminate(const std::string &name) {
    if (burst_.active && burst_.auto_precharge) {
        violation(edge_, "bank state",
                  name + ": the running " + (burst_.write ? "WRITE" : "READ") + " with auto precharge (bank " +
                      std::to_string(burst_.bank) + ", " + when(burst_.start_edge) + ") may not be terminated");
        return;
    }
    end_burst(edge_);
}

// Word k of a burst: the data sheet's burst definition (p. 26): within a block of the burst length,
// sequential wraps, interleaved is start XOR k; a full page wraps at the end of the row.
uint32_t SdramChip::burst_col(const Burst &b, uint32_t k) const {
    if (b.full_page) return (b.start_col + k) & col_mask_;
    const uint32_t m = b.length - 1;
    const uint32_t offset = b.start_col & m;
    return (b.start_col & ~m) | (b.interleaved ? (offset ^ k) : ((offset + k) & m));
}

void SdramChip::step_burst(const SdramPins &p) {
    if (!burst_.active) return;
    const int64_t e = edge_;
    const uint32_t col = burst_col(burst_, burst_.index);
    if (burst_.write) {
        const uint8_t enabled = ~p.dqm & 3;
        if (enabled != 0) {
            if (!p.dq_driven) {
                violation(e, "DQ",
                          "WRITE bank " + std::to_string(burst_.bank) + " row " + std::to_string(burst_.row) +
                              " column " + std::to_string(col) +
                              ": the controller does not drive DQ at a data edge with DQM low");
            }
            Page &pg = page(burst_.bank, burst_.row);
            const uint16_t mask = (enabled & 1 ? 0x00FF : 0) | (enabled & 2 ? 0xFF00 : 0);
            pg.data[col] = static_cast<uint16_t>((pg.data[col] & ~mask) | (p.dq_in & mask));
            pg.written[col] |= enabled;
            banks_[burst_.bank].last_write_edge = e;
            ++counters_.words_written;
        }
    } else {
        OutWord w{e + burst_.cas_latency, 0, 0, burst_.bank, burst_.row, col};
        if (const Page *pg = find_page(burst_.bank, burst_.row)) {
            w.data = pg->data[col];
            w.written = pg->written[col];
        }
        pipe_[(pipe_head_ + pipe_count_) & kPipeMask] = w;
        ++pipe_count_;
    }
    ++burst_.index;
    if (!burst_.full_page && burst_.index == burst_.length) burst_.active = false;
}

// The read word valid at the next edge, masked by the DQM sampled at the previous edge (latency 2).
SdramDrive SdramChip::drive_out() {
    const int64_t e = edge_;
    SdramDrive d{0, false, 0};
    while (pipe_count_ != 0 && pipe_[pipe_head_].valid_edge <= e) {
        pipe_head_ = (pipe_head_ + 1) & kPipeMask;
        --pipe_count_;
    }
    if (pipe_count_ == 0 || pipe_[pipe_head_].valid_edge != e + 1) return d;
    const OutWord w = pipe_[pipe_head_];
    pipe_head_ = (pipe_head_ + 1) & kPipeMask;
    --pipe_count_;
    const uint8_t enabled = ~dqm_prev_ & 3;
    if (enabled == 0) return d;
    uint16_t v = w.data;
    const uint8_t missing = enabled & ~w.written;
    if (missing != 0) {
        ++counters_.uninitialised_reads;
        if (cfg_.strict_uninitialised_reads) {
            violation(e, "uninitialised",
                      "READ bank " + std::to_string(w.bank) + " row " + std::to_string(w.row) + " column " +
                          std::to_string(w.col) + ": " + (missing == 3 ? "the word" : "a byte of the word") +
                          " was never written (uninitialised read)");
        }
        const uint16_t m = (missing & 1 ? 0x00FF : 0) | (missing & 2 ? 0xFF00 : 0);
        v = static_cast<uint16_t>((v & ~m) | (cfg_.uninitialised_value & m));
    }
    const uint16_t mask = (enabled & 1 ? 0x00FF : 0) | (enabled & 2 ? 0xFF00 : 0);
    d.dq = v & mask;
    d.oe = true;
    d.byte_oe = enabled;
    driven_ = w;
    ++counters_.words_read;
    return d;
}

// The oldest refresh whose 8,192nd successor has not come yet: refresh n - 8191 (or 0, the end of
// initialisation, before there were 8,192).
uint64_t SdramChip::window_start() const {
    return refresh_n_ + 1 >= cfg_.refresh_count ? refresh_n_ + 1 - cfg_.refresh_count : 0;
}

// The next refresh is due by the earlier of: 9 x tREFI after the last one (8 postponed), and 64 ms
// after window_start() (so that every 64 ms window holds 8,192).
void SdramChip::set_refresh_deadline() {
    refresh_deadline_ = refresh_last_ + c_refresh_gap_;
    refresh_deadline_is_window_ = false;
    const int64_t window = refresh_ring_[window_start() % cfg_.refresh_count] + c_refresh_window_;
    if (window < refresh_deadline_) {
        refresh_deadline_ = window;
        refresh_deadline_is_window_ = true;
    }
}

void SdramChip::refresh_overdue(int64_t edge, bool at_finish) {
    refresh_reported_ = true;
    const std::string end = at_finish ? "at the end of the run, " : "";
    if (!refresh_deadline_is_window_) {
        violation(edge, "tREFI",
                  end + "refresh overdue: no AUTO REFRESH for " +
                      time_text(static_cast<uint64_t>(edge - refresh_last_) * cfg_.clock_period_ps) + " (the last at " +
                      when(refresh_last_) + "): tREFI " + time_text(cfg_.tREF_ps / cfg_.refresh_count) +
                      " with up to " + std::to_string(cfg_.refresh_postpone) + " postponed allows " +
                      time_text(refresh_gap_ps()) + " between refreshes");
    } else {
        const uint64_t first = window_start();
        violation(edge, "tREF",
                  end + "refresh overdue: only " + std::to_string(refresh_n_ - first) + " AUTO REFRESH in the " +
                      time_text(cfg_.tREF_ps) + " after " + when(refresh_ring_[first % cfg_.refresh_count]) +
                      (first == 0 ? " (the end of initialisation)" : "") + ": tREF needs " +
                      std::to_string(cfg_.refresh_count) + " in every " + time_text(cfg_.tREF_ps));
    }
}

void SdramChip::finish() { finish(static_cast<uint64_t>(edge_)); }

void SdramChip::finish(uint64_t edge_u) {
    const int64_t edge = static_cast<int64_t>(edge_u);
    if (edge <= finished_edge_) return;
    finished_edge_ = edge;
    if (init_done_ && cfg_.check_refresh && !refresh_reported_ && edge > refresh_deadline_) {
        refresh_overdue(edge, true);
    }
    for (uint32_t j = 0; j < cfg_.banks; ++j) {
        Bank &k = banks_[j];
        if (!k.open || k.tras_max_reported) continue;
        const uint64_t open_ps = static_cast<uint64_t>(edge - k.act_edge) * cfg_.clock_period_ps;
        if (open_ps > cfg_.tRAS_max_ps) {
            k.tras_max_reported = true;
            violation(edge, "tRAS max",
                      "at the end of the run, bank " + std::to_string(j) + " row " + std::to_string(k.row) +
                          " has been open for " + time_text(open_ps) + " (from " + when(k.act_edge) + "): tRAS max " +
                          time_text(cfg_.tRAS_max_ps));
        }
    }
}

std::string SdramChip::stats() const {
    std::string s;
    for (size_t i = static_cast<size_t>(SdramCommand::kActive); i < kCommandKinds; ++i) {
        s += std::string(s.empty() ? "" : " ") + kShortName[i] + " " + std::to_string(counters_.commands[i]);
    }
    s += "; " + std::to_string(counters_.refreshes) + " refreshes after init (longest gap " +
         time_text(counters_.longest_refresh_gap_ps) + "); words read " + std::to_string(counters_.words_read) +
         ", written " + std::to_string(counters_.words_written) + ", uninitialised " +
         std::to_string(counters_.uninitialised_reads) + "; row hits " + std::to_string(counters_.row_hits) +
         ", misses " + std::to_string(counters_.row_misses) + "; " + std::to_string(counters_.pages) + " rows stored; " +
         std::to_string(error_count_) + " violations";
    return s;
}

SdramChip::Page &SdramChip::page(uint32_t bank, uint32_t row) {
    auto it = pages_.find(bank * cfg_.rows + row);
    if (it == pages_.end()) {
        Page pg;
        pg.data.assign(cfg_.cols, 0);
        pg.written.assign(cfg_.cols, 0);
        it = pages_.emplace(bank * cfg_.rows + row, std::move(pg)).first;
        counters_.pages = pages_.size();
    }
    return it->second;
}

const SdramChip::Page *SdramChip::find_page(uint32_t bank, uint32_t row) const {
    auto it = pages_.find(bank * cfg_.rows + row);
    return it == pages_.end() ? nullptr : &it->second;
}

bool SdramChip::peek(uint32_t bank, uint32_t row, uint32_t col, uint16_t *value) const {
    const Page *pg = find_page(bank & (cfg_.banks - 1), row & (cfg_.rows - 1));
    col &= col_mask_;
    const uint8_t written = pg ? pg->written[col] : 0;
    const uint16_t m = (written & 1 ? 0x00FF : 0) | (written & 2 ? 0xFF00 : 0);
    *value = static_cast<uint16_t>(((pg ? pg->data[col] : 0) & m) | (cfg_.uninitialised_value & ~m));
    return written == 3;
}

void SdramChip::poke(uint32_t bank, uint32_t row, uint32_t col, uint16_t value) {
    Page &pg = page(bank & (cfg_.banks - 1), row & (cfg_.rows - 1));
    pg.data[col & col_mask_] = value;
    pg.written[col & col_mask_] = 3;
}
