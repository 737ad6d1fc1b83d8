// SpiFlash: see spi_flash.h. Written from the ISSI IS25LP128 data sheet's command descriptions alone
// (and the numbers the header lists with their sources): a command is its opcode, then its address,
// dummy clocks and data, bit by bit on SCK's edges.
#include "spi_flash.h"

#include <cstdio>
#include <fstream>
#include <iterator>
#include <stdexcept>

namespace {

constexpr uint8_t kRead = 0x03;
constexpr uint8_t kFastRead = 0x0B;
constexpr uint8_t kRdid = 0x9F;
constexpr uint8_t kRdsr = 0x05;
constexpr uint8_t kWren = 0x06;
constexpr uint8_t kWrdi = 0x04;
constexpr uint8_t kPageProgram = 0x02;
constexpr uint8_t kSectorErase = 0x20;
constexpr uint8_t kSectorEraseAlt = 0xD7;  // ISSI's own opcode for the same 4 KiB erase
constexpr uint8_t kDeepPowerDown = 0xB9;
constexpr uint8_t kRelease = 0xAB;
constexpr uint8_t kResetEnable = 0x66;
constexpr uint8_t kReset = 0x99;

constexpr uint32_t kAddressBits = 24;

bool power_of_two(uint64_t v) { return v != 0 && (v & (v - 1)) == 0; }

uint64_t min_period(uint64_t hz) { return (1000000000000ull + hz - 1) / hz; }

std::string hex(uint32_t v, int digits) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "0x%0*X", digits, v);
    return buf;
}

std::string mhz(uint64_t period_ps) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.2f MHz", 1e6 / static_cast<double>(period_ps));
    return buf;
}

}  // namespace

SpiFlash::SpiFlash(const SpiFlashConfig &cfg) : cfg_(cfg) {
    if (!power_of_two(cfg_.size_bytes) || cfg_.size_bytes < 16 * kSectorBytes || cfg_.size_bytes > (256u << 20) ||
        cfg_.read_max_hz == 0 || cfg_.max_hz == 0) {
        throw std::invalid_argument("SpiFlashConfig: the size is a power of two from 64 KiB to 256 MiB, and both "
                                    "SCK maxima are above 0");
    }
    mask_ = cfg_.size_bytes - 1;
    read_min_period_ps_ = min_period(cfg_.read_max_hz);
    min_period_ps_ = min_period(cfg_.max_hz);
    sectors_.resize(cfg_.size_bytes / kSectorBytes);
    if (cfg_.start_in_deep_power_down) {
        power_down_ = true;
        last_command_ = "power-up (in deep power-down)";
    }
}

std::string SpiFlash::time_text(uint64_t ps) {
    double v;
    const char *unit;
    if (ps < 1000000ull) {
        v = static_cast<double>(ps) / 1e3;
        unit = "ns";
    } else if (ps < 1000000000ull) {
        v = static_cast<double>(ps) / 1e6;
        unit = "us";
    } else if (ps < 1000000000000ull) {
        v = static_cast<double>(ps) / 1e9;
        unit = "ms";
    } else {
        v = static_cast<double>(ps) / 1e12;
        unit = "s";
    }
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3f", v);
    std::string s = buf;
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
    return s + " " + unit;
}

std::string SpiFlash::command_name(uint8_t op) {
    switch (op) {
    case kRead: return "READ (0x03)";
    case kFastRead: return "FAST READ (0x0B)";
    case kRdid: return "RDID (0x9F)";
    case kRdsr: return "RDSR (0x05)";
    case kWren: return "WREN (0x06)";
    case kWrdi: return "WRDI (0x04)";
    case kPageProgram: return "PAGE PROGRAM (0x02)";
    case kSectorErase: return "SECTOR ERASE (0x20)";
    case kSectorEraseAlt: return "SECTOR ERASE (0xD7)";
    case kDeepPowerDown: return "DEEP POWER-DOWN (0xB9)";
    case kRelease: return "RELEASE (0xAB)";
    case kResetEnable: return "RESET ENABLE (0x66)";
    case kReset: return "RESET (0x99)";
    default: return "opcode " + hex(op, 2);
    }
}

bool SpiFlash::has_address() const {
    return opcode_ == kRead || opcode_ == kFastRead || opcode_ == kPageProgram || opcode_ == kSectorErase ||
           opcode_ == kSectorEraseAlt;
}

std::string SpiFlash::command_text() const {
    if (!decoded_) return "(incomplete opcode)";
    std::string s = command_name(opcode_);
    if (addr_done_ && has_address()) s += " at " + hex(cmd_addr_, 6);
    return s;
}

void SpiFlash::violation(uint64_t t, const char *rule, const std::string &what) {
    ++error_count_;
    const std::string command = command_text();
    const std::string text = "spiflash: " + time_text(t) + ": " + command + ": " + what + " [" + rule + "]";
    if (cfg_.fail_fast && error_count_ == 1) std::fprintf(stderr, "%s\n", text.c_str());
    if (errors_.size() < cfg_.max_messages) {
        errors_.push_back(text);
        violations_.push_back({t, rule, command, text});
    }
}

std::string SpiFlash::describe() const {
    if (error_count_ == 0) return "no violations";
    return errors_.empty() ? std::to_string(error_count_) + " violations (none kept)" : errors_.front();
}

SpiFlashOut SpiFlash::step(uint64_t t, bool cs_n, bool sck, bool mosi) {
    if (!started_) {
        started_ = true;
        sck_ = sck;
    } else if (t < t_) {
        throw std::invalid_argument("SpiFlash::step: time went back from " + time_text(t_) + " to " + time_text(t));
    }
    t_ = t;
    if (busy_ && t >= busy_until_) {  // the program / erase is over: WIP and WEL clear
        busy_ = false;
        wel_ = false;
    }
    const bool was_selected = !cs_n_;
    if (cs_n_ && !cs_n) begin_selection(t, sck_);
    if ((was_selected || !cs_n) && sck != sck_) {
        if (sck) {
            on_rise(t, mosi);
        } else {
            on_fall();
        }
    }
    if (!cs_n_ && cs_n) end_selection(t);
    cs_n_ = cs_n;
    sck_ = sck;
    return {miso_, oe_};
}

void SpiFlash::begin_selection(uint64_t t, bool sck_before) {
    ++counters_.selections;
    phase_ = Phase::kOpcode;
    sel_t_ = t;
    if (sck_before) ++counters_.mode3_selections;
    rises_ = 0;
    sel_min_period_ = 0;
    decoded_ = ignored_ = fsck_reported_ = addr_done_ = false;
    opcode_ = 0;
    shift_ = field_ = addr_ = 0;
    out_index_ = out_bit_ = 0;
    page_bytes_in_ = 0;
    page_set_.fill(false);
}

// The checks of the selection's start, made once the command is known (its opcode, or its absence when
// CS# rises within the opcode): CS# high time before it, CS# setup to the first SCK, the opcode's clocks.
void SpiFlash::selection_checks(uint64_t t) {
    if (cs_rose_ && sel_t_ - cs_rise_t_ < cfg_.tCEH_ps) {
        violation(t, "tCEH", "CS# high for " + time_text(sel_t_ - cs_rise_t_) + " after " + last_command_ +
                                 ", tCEH needs " + time_text(cfg_.tCEH_ps));
    }
    if (rises_ > 0 && first_rise_t_ - sel_t_ < cfg_.tCS_ps) {
        violation(t, "tCS", "the first rising SCK edge " + time_text(first_rise_t_ - sel_t_) +
                                " after CS# fell, tCS needs " + time_text(cfg_.tCS_ps));
    }
    if (sel_min_period_ != 0) check_period(sel_min_period_, t);
}

void SpiFlash::check_period(uint64_t period, uint64_t t) {
    if (fsck_reported_ || !decoded_) return;
    const bool read = opcode_ == kRead;
    const uint64_t limit = read ? read_min_period_ps_ : min_period_ps_;
    if (period >= limit) return;
    fsck_reported_ = true;
    violation(t, "fSCK", "SCK period " + time_text(period) + " (" + mhz(period) + "), above the " +
                             mhz(limit) + " this command allows (" + (read ? "fC, normal read" : "fCT") + ")");
}

void SpiFlash::on_rise(uint64_t t, bool mosi) {
    if (rises_ == 0) {
        first_rise_t_ = t;
    } else {
        const uint64_t period = t - last_rise_t_;
        if (sel_min_period_ == 0 || period < sel_min_period_) sel_min_period_ = period;
        if (counters_.min_sck_period_ps == 0 || period < counters_.min_sck_period_ps) {
            counters_.min_sck_period_ps = period;
        }
        check_period(period, t);
    }
    last_rise_t_ = t;
    ++rises_;
    const uint32_t bit = mosi ? 1 : 0;
    switch (phase_) {
    case Phase::kOpcode:
        shift_ = (shift_ << 1) | bit;
        if (rises_ == 8) decode(t);
        break;
    case Phase::kAddress:
        addr_ = (addr_ << 1) | bit;
        if (++field_ == kAddressBits) address_done();
        break;
    case Phase::kDummy:
        if (++field_ == cfg_.fast_read_dummy_clocks) {
            phase_ = Phase::kOutput;
            field_ = 0;
        }
        break;
    case Phase::kOutput:
        // The master samples the bit driven since the last falling edge: a byte is read whole at its 8th.
        if (++field_ % 8 == 0 && (opcode_ == kRead || opcode_ == kFastRead)) ++counters_.bytes_read;
        break;
    case Phase::kProgram:
        shift_ = ((shift_ << 1) | bit) & 0xFF;
        if (++field_ % 8 == 0) {
            const uint32_t i = (addr_ + page_bytes_in_) % kPageBytes;  // wraps within the page
            page_[i] = static_cast<uint8_t>(shift_);
            page_set_[i] = true;
            ++page_bytes_in_;
        }
        break;
    case Phase::kIdle:
    case Phase::kTail:
    case Phase::kIgnore:
        break;
    }
}

void SpiFlash::on_fall() {
    if (phase_ != Phase::kOutput) return;
    if (out_bit_ == 0) out_byte_ = next_output_byte();
    miso_ = ((out_byte_ >> (7 - out_bit_)) & 1) != 0;
    oe_ = true;
    out_bit_ = (out_bit_ + 1) & 7;
}

uint8_t SpiFlash::next_output_byte() {
    const uint32_t k = out_index_++;
    switch (opcode_) {
    case kRead:
    case kFastRead: {
        const uint8_t v = read_byte(addr_);
        addr_ = (addr_ + 1) & mask_;  // wraps at the end of the array
        return v;
    }
    case kRdid: return cfg_.jedec_id[k % 3];
    case kRdsr: return status();  // read afresh for every repetition
    case kRelease: return cfg_.electronic_id;
    default: return 0xFF;
    }
}

void SpiFlash::decode(uint64_t t) {
    opcode_ = static_cast<uint8_t>(shift_);
    decoded_ = true;
    ++counters_.commands[opcode_];
    field_ = 0;
    selection_checks(t);

    // The device's state at CS# fall decides whether it takes the command.
    if (power_down_) {
        if (sel_t_ < power_down_at_) {
            violation(t, "tDP", "begun " + time_text(sel_t_ - power_down_from_) + " after DEEP POWER-DOWN, tDP needs " +
                                    time_text(cfg_.tDP_ps) + (opcode_ == kRelease ? "" : "; ignored"));
            if (opcode_ != kRelease) {
                ignored_ = true;
                phase_ = Phase::kIgnore;
                return;
            }
        } else if (opcode_ != kRelease) {
            violation(t, "deep power-down", "in deep power-down, where only RELEASE (0xAB) is taken; ignored");
            ignored_ = true;
            phase_ = Phase::kIgnore;
            return;
        }
    } else if (sel_t_ < ready_at_) {
        violation(t, ready_rule_, "begun " + time_text(sel_t_ - ready_from_) + " after " + ready_after_ + ", " +
                                      ready_rule_ + " needs " + time_text(ready_at_ - ready_from_));
    }
    if (sel_t_ < busy_until_ && opcode_ != kRdsr) {
        violation(t, "busy", "while " + busy_what_ + " runs (WIP) until " + time_text(busy_until_) +
                                 ": only RDSR is taken; ignored");
        ignored_ = true;
        phase_ = Phase::kIgnore;
        return;
    }

    switch (opcode_) {
    case kRead:
    case kFastRead:
    case kPageProgram:
    case kSectorErase:
    case kSectorEraseAlt:
    case kRelease:  // 24 dummy bits before the electronic ID; CS# may rise before them (release only)
        phase_ = Phase::kAddress;
        break;
    case kRdid:
    case kRdsr:
        phase_ = Phase::kOutput;
        break;
    case kWren:
    case kWrdi:
    case kDeepPowerDown:
    case kResetEnable:
    case kReset:
        phase_ = Phase::kTail;
        break;
    default:
        violation(t, "opcode", "not a command this model carries; ignored");
        ignored_ = true;
        phase_ = Phase::kIgnore;
        break;
    }
}

void SpiFlash::address_done() {
    addr_ &= (1u << kAddressBits) - 1;
    if (opcode_ != kRelease) addr_ &= mask_;  // a part under 16 MiB ignores the upper address bits
    cmd_addr_ = addr_;
    addr_done_ = true;
    field_ = 0;
    switch (opcode_) {
    case kRead:
        phase_ = Phase::kOutput;
        break;
    case kFastRead:
        phase_ = cfg_.fast_read_dummy_clocks == 0 ? Phase::kOutput : Phase::kDummy;
        break;
    case kPageProgram:
        shift_ = 0;
        phase_ = Phase::kProgram;
        break;
    case kRelease:
        phase_ = Phase::kOutput;
        break;
    default:  // SECTOR ERASE
        phase_ = Phase::kTail;
        break;
    }
}

// A command of a fixed length ends at exactly `bytes` bytes; otherwise the data sheet ignores it.
bool SpiFlash::exact_length(uint32_t bytes) {
    if (rises_ == bytes * 8) return true;
    if (rises_ % 8 != 0) {
        violation(t_, "byte boundary", "CS# rose after " + std::to_string(rises_) +
                                           " clocks, within a byte; ignored");
    } else {
        violation(t_, "length", "CS# rose after " + std::to_string(rises_ / 8) + " bytes, the command has " +
                                    std::to_string(bytes) + "; ignored");
    }
    return false;
}

void SpiFlash::start_busy(uint64_t t, uint64_t duration, const std::string &what) {
    busy_ = true;
    busy_until_ = t + duration;
    busy_what_ = what;
}

void SpiFlash::execute(uint64_t t, bool reset_armed) {
    switch (opcode_) {
    case kWren:
        if (exact_length(1)) wel_ = true;
        break;
    case kWrdi:
        if (exact_length(1)) wel_ = false;
        break;
    case kDeepPowerDown:
        if (exact_length(1)) {
            power_down_ = true;
            power_down_from_ = t;
            power_down_at_ = t + cfg_.tDP_ps;
        }
        break;
    case kResetEnable:
        if (exact_length(1)) reset_enabled_ = true;
        break;
    case kReset:
        if (!exact_length(1)) break;
        if (!reset_armed) {
            violation(t, "reset enable", "not right after RESET ENABLE (0x66); ignored");
            break;
        }
        wel_ = false;
        ready_from_ = t;
        ready_at_ = t + cfg_.tRST_ps;
        ready_rule_ = "tRST";
        ready_after_ = command_name(kReset);
        break;
    case kRelease:
        if (power_down_) {  // the release form and the RES form alike, wherever CS# rises
            power_down_ = false;
            ready_from_ = t;
            ready_at_ = t + cfg_.tRES1_ps;
            ready_rule_ = "tRES1";
            ready_after_ = command_name(kRelease);
        }
        break;
    case kSectorErase:
    case kSectorEraseAlt: {
        if (!exact_length(4)) break;
        if (!wel_) {
            violation(t, "WEL", "without WREN (the write enable latch is clear); ignored");
            break;
        }
        sectors_[addr_ / kSectorBytes] = std::vector<uint8_t>();
        ++counters_.sectors_erased;
        start_busy(t, cfg_.tSE_ps, command_text());
        break;
    }
    case kPageProgram: {
        if (rises_ % 8 != 0) {
            violation(t, "byte boundary",
                      "CS# rose after " + std::to_string(rises_) + " clocks, within a byte; ignored");
            break;
        }
        if (page_bytes_in_ == 0) {
            violation(t, "length", "CS# rose before the first data byte; ignored");
            break;
        }
        if (!wel_) {
            violation(t, "WEL", "without WREN (the write enable latch is clear); ignored");
            break;
        }
        const uint32_t base = addr_ & ~(kPageBytes - 1);
        for (uint32_t i = 0; i < kPageBytes; ++i) {
            if (!page_set_[i]) continue;
            write_byte(base + i, static_cast<uint8_t>(read_byte(base + i) & page_[i]));  // 1 -> 0 only
            ++counters_.bytes_programmed;
        }
        ++counters_.pages_programmed;
        start_busy(t, cfg_.tPP_ps, command_text());
        break;
    }
    default:  // the reads: nothing happens at CS# rise
        break;
    }
}

void SpiFlash::end_selection(uint64_t t) {
    if (rises_ > 0 && !decoded_) {
        selection_checks(t);
        violation(t, "byte boundary", "CS# rose after " + std::to_string(rises_) + " clocks, within the opcode");
    }
    if (rises_ > 0 && t - last_rise_t_ < cfg_.tCH_ps) {
        violation(t, "tCH", "CS# rose " + time_text(t - last_rise_t_) + " after the last rising SCK edge, tCH needs " +
                                time_text(cfg_.tCH_ps));
    }
    if (decoded_) {
        const bool reset_armed = reset_enabled_;
        reset_enabled_ = false;  // RESET ENABLE holds for the next command only
        if (!ignored_) execute(t, reset_armed);
        last_command_ = command_text();
    } else if (rises_ > 0) {
        last_command_ = "an incomplete opcode";
    }
    phase_ = Phase::kIdle;
    miso_ = oe_ = false;
    cs_rose_ = true;
    cs_rise_t_ = t;
}

bool SpiFlash::read_in_progress() const {
    return !cs_n_ && phase_ == Phase::kOutput && (opcode_ == kRead || opcode_ == kFastRead);
}

uint8_t SpiFlash::read_byte(uint32_t addr) const {
    const std::vector<uint8_t> &s = sectors_[addr / kSectorBytes];
    return s.empty() ? 0xFF : s[addr % kSectorBytes];
}

void SpiFlash::write_byte(uint32_t addr, uint8_t v) {
    std::vector<uint8_t> &s = sectors_[addr / kSectorBytes];
    if (s.empty()) {
        if (v == 0xFF) return;
        s.assign(kSectorBytes, 0xFF);
    }
    s[addr % kSectorBytes] = v;
}

void SpiFlash::load(uint32_t offset, const uint8_t *data, size_t n) {
    if (offset > cfg_.size_bytes || n > cfg_.size_bytes - offset) {
        throw std::out_of_range("SpiFlash::load: " + std::to_string(n) + " bytes at " + hex(offset, 6) +
                                " do not fit the " + std::to_string(cfg_.size_bytes) + "-byte array");
    }
    for (size_t i = 0; i < n; ++i) write_byte(static_cast<uint32_t>(offset + i), data[i]);
}

bool SpiFlash::load_file(uint32_t offset, const std::string &path, std::string *error) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        *error = "cannot open " + path;
        return false;
    }
    const std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (offset > cfg_.size_bytes || bytes.size() > cfg_.size_bytes - offset) {
        *error = path + ": " + std::to_string(bytes.size()) + " bytes at " + hex(offset, 6) + " do not fit the " +
                 std::to_string(cfg_.size_bytes) + "-byte flash";
        return false;
    }
    load(offset, bytes);
    return true;
}

std::vector<uint8_t> SpiFlash::read_backdoor(uint32_t offset, size_t n) const {
    if (offset > cfg_.size_bytes || n > cfg_.size_bytes - offset) {
        throw std::out_of_range("SpiFlash::read_backdoor: " + std::to_string(n) + " bytes at " + hex(offset, 6) +
                                " are past the end of the array");
    }
    std::vector<uint8_t> out(n);
    for (size_t i = 0; i < n; ++i) out[i] = read_byte(static_cast<uint32_t>(offset + i));
    return out;
}

uint8_t SpiFlash::peek(uint32_t addr) const {
    if (addr >= cfg_.size_bytes) throw std::out_of_range("SpiFlash::peek: " + hex(addr, 6) + " is past the end");
    return read_byte(addr);
}

std::string SpiFlash::stats() const {
    std::string s;
    for (uint32_t op = 0; op < 256; ++op) {
        if (counters_.commands[op] == 0) continue;
        s += std::string(s.empty() ? "" : ", ") + command_name(static_cast<uint8_t>(op)) + " " +
             std::to_string(counters_.commands[op]);
    }
    if (s.empty()) s = "no commands";
    s += "; " + std::to_string(counters_.bytes_read) + " bytes read, " + std::to_string(counters_.bytes_programmed) +
         " programmed (" + std::to_string(counters_.pages_programmed) + " pages), " +
         std::to_string(counters_.sectors_erased) + " sectors erased; shortest SCK period " +
         (counters_.min_sck_period_ps ? time_text(counters_.min_sck_period_ps) : std::string("-")) + "; " +
         std::to_string(error_count_) + " violations";
    return s;
}
