// rtl_check: seeded random batches driven into the RTL and the golden model through the same bus
// writes. After every batch, every read-only register except the cycle counter must agree, and the
// framebuffer being drawn (the back buffer) must equal the model's pixel for pixel — read from the
// RTL's framebuffer RAMs (GpuSim::back_buffer), since a batch that does not swap shows nothing on the
// VGA pins; every frame a swap shows is also captured from the VGA pins and must equal the model's.
// Prints a reproducer on failure.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "gpu_sim.h"
#include "model_check.h"
#include "rng.h"

extern "C" {
#include "gpu_regs.h"
}

namespace {

struct Frame {  // the GPU's frame, in pixels (its build's, GpuSim::build_config)
    int32_t w, h;
};

struct Vertex {
    int32_t x, y;  // Q12.4, kept within int16
};

int16_t clamp16(int32_t v) { return static_cast<int16_t>(v < -32768 ? -32768 : (v > 32767 ? 32767 : v)); }

// A vertex from one of several families that stress different parts of the rule.
Vertex random_vertex(Rng &r, int family, Vertex anchor, Frame fb)
{
    switch (family) {
    case 0:  // anywhere on screen and a little beyond
        return {r.range(-32 * 16, (fb.w + 32) * 16), r.range(-32 * 16, (fb.h + 32) * 16)};
    case 1:  // near the anchor: small and sub-pixel triangles
        return {anchor.x + r.range(-40, 40), anchor.y + r.range(-40, 40)};
    case 2:  // exactly on pixel centres, to land edges on sample points
        return {r.range(-2, fb.w + 2) * 16 + 8, r.range(-2, fb.h + 2) * 16 + 8};
    case 3:  // centres shifted by +-1/16 px
        return {r.range(0, fb.w - 1) * 16 + 8 + r.range(-1, 1), r.range(0, fb.h - 1) * 16 + 8 + r.range(-1, 1)};
    default:  // the whole Q12.4 range, guard-band corners included
        if (r.chance(30)) {
            return {r.chance(50) ? -32768 : 32767, r.chance(50) ? -32768 : 32767};
        }
        return {r.range(-32768, 32767), r.range(-32768, 32767)};
    }
}

struct Writer {  // every bus write goes to both implementations
    GpuSim &sim;
    ModelCheck &model;
    void operator()(uint32_t offset, uint32_t value)
    {
        sim.write(offset, value);
        model.write(offset, value);
    }
};

// "" when the RTL's back buffer equals the model's, else how they differ.
std::string compare_back_buffer(const GpuSim &sim, const ModelCheck &model, std::vector<uint8_t> &rtl)
{
    sim.back_buffer(rtl.data());
    const uint8_t *expected = gpu_model_back(model.model());
    long mismatches = 0, first = -1;
    for (long i = 0; i < static_cast<long>(rtl.size()); i++) {
        if (rtl[i] != expected[i]) {
            first = first < 0 ? i : first;
            mismatches++;
        }
    }
    if (mismatches == 0) {
        return "";
    }
    char text[160];
    std::snprintf(text, sizeof text, "back buffer: %ld pixels differ; first at fb (%ld,%ld): RTL %u, model %u",
                  mismatches, first % static_cast<long>(model.model()->cfg.fb_width),
                  first / static_cast<long>(model.model()->cfg.fb_width), rtl[first], expected[first]);
    return text;
}

}  // namespace

int rtl_check_main(int argc, char **argv)
{
    uint64_t seed = 1;
    int batches = 40;
    int max_tris = 48;
    uint64_t min_prims = 0;     // fail unless at least this many primitives were checked
    uint64_t min_overflows = 0;  // fail unless at least this many batches set ERR_COUNT
    uint32_t swap_percent = 80;
    unsigned throttle = 0;       // percent of clocks the back frame refuses a span (fast path) or
                                 // the frames' memory port refuses a command (FRAME_DRAM)
    for (int i = 0; i + 1 < argc; i += 2) {
        const std::string a = argv[i];
        if (a == "--seed") {
            seed = std::strtoull(argv[i + 1], nullptr, 0);
        } else if (a == "--batches") {
            batches = std::atoi(argv[i + 1]);
        } else if (a == "--tris") {
            max_tris = std::atoi(argv[i + 1]);
        } else if (a == "--swap-percent") {
            swap_percent = static_cast<uint32_t>(std::atoi(argv[i + 1]));
        } else if (a == "--min-prims") {
            min_prims = std::strtoull(argv[i + 1], nullptr, 0);
        } else if (a == "--min-overflows") {
            min_overflows = std::strtoull(argv[i + 1], nullptr, 0);
        } else if (a == "--frame-throttle") {
            throttle = static_cast<unsigned>(std::atoi(argv[i + 1]));
        } else {
            std::fprintf(stderr, "usage: gpusim random [--seed N] [--batches N] [--tris N] [--min-prims N] [--min-overflows N] "
                                 "[--swap-percent P] [--frame-throttle P]\n");
            return 2;
        }
    }

    Rng r{seed};
    GpuSim sim;
    // The back frame busy on some clocks (a strip build's flushes must wait for it, losing nothing).
    if (throttle != 0 && !sim.throttle_frame(throttle, seed ^ 0x5448524Full)) {
        std::fprintf(stderr, "random: --frame-throttle needs the fast display path (gpu_core's frame port) or frames in "
                             "external memory, and 0 .. 100\n");
        return 2;
    }
    const gpu_model_config cfg = GpuSim::build_config();
    ModelCheck model(cfg);
    // The buffers' capacities this GPU was built with (the model has the same). On a GPU built with
    // smaller ones than the contract's, a quarter of the batches go past them: BASE anywhere below
    // the capacity, COUNT as for the full GPU, so BASE + COUNT mostly overflows (ERR_COUNT, nothing
    // drawn) and the buffer words written past the capacity land on unmapped offsets (ignored, not
    // wrapped into the buffer: a later batch would draw them). The full GPU draws no extra numbers,
    // so its seeds' batches are as before.
    const uint32_t vcap = cfg.vtx_cap, tcap = cfg.tri_cap;
    const bool small_caps = vcap < GPU_VTX_CAP || tcap < GPU_TRI_CAP;
    if (vcap < 3 || tcap < 1) {
        std::fprintf(stderr, "random: VTX_CAP %u / TRI_CAP %u hold no triangle\n", vcap, tcap);
        return 2;
    }
    // Gouraud triangles: a good share of the primitives where the GPU has them; a few elsewhere,
    // where each must be refused with ERR_KIND.
    const uint32_t gouraud_percent = cfg.gouraud ? 40 : 2;
    uint64_t shaded = 0;
    Writer write{sim, model};
    const bool wmask = (sim.read(GPU_REG_CAPS) & GPU_CAPS_WMASK_MASK) != 0;
    uint64_t tris = 0, pixels = 0, frames = 0, resets = 0, back_checks = 0, overflows = 0, index_errors = 0;
    uint64_t masked = 0, strips = 0, walks = 0;
    // STRIP draws from a stream of its own, so that the other draws of a seed stay as they were.
    Rng rs{seed ^ 0x5354524950ull};
    const Frame fb{static_cast<int32_t>(cfg.fb_width), static_cast<int32_t>(cfg.fb_height)};
    std::vector<uint8_t> back(static_cast<std::size_t>(fb.w) * static_cast<std::size_t>(fb.h));
    bool must_clear = false;
    // A strip build's strip height, and the strip a RESET probe drew into (opened again after it).
    const uint32_t strip_rows = cfg.strip_rows;
    uint32_t reset_strip = 0;
    // A strip build's clear colour: mostly the same from batch to batch, as a frame's strips clear
    // (a strip then opens in a bank its last flush already cleared to that colour, and skips the
    // clear: gpu_raster); changed now and then, and a batch's own on some batches.
    uint32_t strip_colour = 0;
    uint64_t strip_refusals = 0;

    // The power-on registers first (ID, CAPS, VTX_CAP, TRI_CAP ...): a model of another build says
    // so here, before any batch could fail for that reason less plainly.
    if (const std::string diff = model.compare_registers(sim); !diff.empty()) {
        std::printf("random: at power-on, %s\n", diff.c_str());
        return 1;
    }

    // Contract probes the random batches cannot reach: a write while busy is dropped and flagged,
    // and the write-only windows read 0.
    write(GPU_REG_CTRL, GPU_CTRL_CLEAR_MASK);
    write(GPU_REG_DOORBELL, 0xB0B0);
    sim.write(GPU_WIN_VTX, 0x12345678);  // during the clear: dropped (the model never sees it)
    if (!sim.wait_done(0xB0B0, 1000000) || !(sim.read(GPU_REG_ERRORS) & GPU_ERR_WRITE_BUSY_MASK) ||
        sim.read(GPU_WIN_VTX) != 0 || sim.read(GPU_WIN_PALETTE) != 0) {
        std::printf("random: a write while busy was not flagged with ERR_WRITE_BUSY, or a write-only window read non-zero\n");
        return 1;
    }

    for (int p = 0; p < 256; p++) {
        write(GPU_WIN_PALETTE + 4 * p, r.below(4096));
    }
    for (int b = 0; b < batches; b++) {
        // Buffers at random places inside the capacity (or, past, beyond it: above; some then drawn
        // clipped to it, below).
        // (Not after a RESET: the batch must clear what the abandoned one left; ERR_COUNT would skip it.)
        const bool past = small_caps && !must_clear && r.chance(25);
        const uint32_t nv = 3 + r.below(past ? 61 : std::min<uint32_t>(61, vcap - 2));
        const uint32_t nt = 1 + r.below(std::min<uint32_t>(static_cast<uint32_t>(max_tris), past ? GPU_TRI_CAP : tcap));
        const uint32_t vbase = past ? r.below(vcap) : r.below(vcap - nv + 1);
        const uint32_t tbase = past ? r.below(tcap) : r.below(tcap - nt + 1);
        const int family = static_cast<int>(r.below(5));
        // Intensities (VTX_I, Q4.12) of this batch: anywhere, only the extremes 0 and 65535, or
        // close together (slow gradients, where the fraction and the dither decide).
        const uint32_t ifamily = r.below(3);
        const uint32_t ibase = r.below(65536);
        uint64_t batch_shaded = 0;  // counted once the batch is checked
        Vertex anchor = {r.range(0, fb.w * 16), r.range(0, fb.h * 16)};
        for (uint32_t v = 0; v < nv; v++) {
            if (family == 1 && r.chance(20)) {
                anchor = {r.range(0, fb.w * 16), r.range(0, fb.h * 16)};
            }
            Vertex vx = random_vertex(r, r.chance(80) ? family : static_cast<int>(r.below(5)), anchor, fb);
            const uint32_t word = static_cast<uint16_t>(clamp16(vx.x)) | static_cast<uint32_t>(static_cast<uint16_t>(clamp16(vx.y))) << 16;
            write(GPU_WIN_VTX + 8 * (vbase + v), word);
            uint32_t inten = ifamily == 0 ? r.below(65536) : ifamily == 1 ? (r.chance(50) ? 0u : 65535u)
                                                                       : std::min<uint32_t>(65535, ibase + r.below(600));
            write(GPU_WIN_VTX + 8 * (vbase + v) + 4, r.below(65536) | inten << GPU_VTX_I_LSB);
        }
        for (uint32_t t = 0; t < nt; t++) {
            uint32_t i0 = r.below(nv), i1 = r.below(nv), i2 = r.below(nv);
            if (r.chance(3)) {
                i1 = nv + r.below(65536 - nv);  // beyond VTX_COUNT
            }
            uint32_t kind = GPU_PRIM_KIND_TRI;
            if (r.chance(12)) {
                kind = r.chance(85) ? GPU_PRIM_KIND_LINE : r.below(256);
            } else if (r.chance(gouraud_percent)) {
                kind = GPU_PRIM_KIND_TRI_GOURAUD;
                batch_shaded++;
            }
            write(GPU_WIN_IDX + 8 * (tbase + t), i0 | i1 << 16);
            write(GPU_WIN_IDX + 8 * (tbase + t) + 4, i2 | r.below(256) << 16 | kind << 24);
        }
        const bool over_capacity = !must_clear && r.chance(4);  // it would skip the clear
        // Now and then a watchdog's RESET lands in the middle of a batch that does not swap; the
        // next batch then clears, which makes RTL and model agree again (the model has no "middle").
        // (Not on a batch past the capacities: it ends at once, before the RESET could land.)
        // (In a strip build only into a strip already open, which the RESET then drops and the next
        // batch opens anew: RTL and model then agree on every row again.)
        const bool reset_probe = !over_capacity && !past && r.chance(5) && b != batches - 1
                              && (strip_rows == 0 || model.model()->open_strip >= 0);
        const bool swap = !reset_probe && (r.chance(swap_percent) || b == batches - 1);
        const bool clear_forced = must_clear;
        bool clear = r.chance(50) || b == 0 || must_clear;
        must_clear = reset_probe;
        // Half the batches past the capacities draw the part of them inside: had the words written
        // beyond wrapped around into the buffers (RTL or model), the primitives drawn would differ.
        const bool clip = past && r.chance(50);
        const uint32_t vcount = clip ? std::min(nv, vcap - vbase) : nv;
        const uint32_t tcount = clip ? std::min(nt, tcap - tbase) : nt;
        write(GPU_WIN_REGS + GPU_REG_VTX_BASE, vbase);
        write(GPU_WIN_REGS + GPU_REG_VTX_COUNT, over_capacity ? vcap : vcount);
        write(GPU_WIN_REGS + GPU_REG_TRI_BASE, tbase);
        write(GPU_WIN_REGS + GPU_REG_TRI_COUNT, tcount);
        const uint32_t batch_colour = r.below(256);
        if (strip_rows != 0 && rs.chance(5)) {
            strip_colour = batch_colour;
        }
        write(GPU_WIN_REGS + GPU_REG_CLEAR_COLOR, (strip_rows == 0 || rs.chance(15)) ? batch_colour : strip_colour);
        // The write mask on some batches: any of the four plane sets (none, low, high, both), the
        // clear included, with junk in the undefined bits; both planes on the others, and on the
        // clear after a RESET probe, which must overwrite every bit the aborted batch left.
        uint32_t planes = (r.chance(40) && !clear_forced) ? r.below(4) : 3u;
        const uint32_t planes_junk = r.below(64) << 2;
        // A band of rows on some batches (contract "Strips"): anywhere in the frame, one row to
        // half of it, now and then past the frame's end or empty (first after last); the whole
        // frame on the others, and on the clear after a RESET probe.
        uint32_t strip = static_cast<uint32_t>(fb.h - 1) << GPU_STRIP_LAST_LSB;
        if (strip_rows == 0 && !clear_forced && rs.chance(40)) {
            const uint32_t first = rs.below(static_cast<uint32_t>(fb.h) + 8u);
            uint32_t last = first + rs.below(static_cast<uint32_t>(fb.h) / 2u);
            last = rs.chance(10) ? 0xFFFFu : (rs.chance(10) && first > 0 ? first - 1u : last);
            strip = first | (last << GPU_STRIP_LAST_LSB);
            strips++;
        }
        bool ztest = r.chance(60);  // depth test (a no-op without CAPS_ZBUF: the bits are then ignored)
        bool zclear = r.chance(30) || b == 0 || clear_forced;  // a reset may also leave the depths half done
        const bool dither = r.chance(50);  // ordered dithering of Gouraud triangles (ignored without CAPS_GOURAUD)
        // CTRL.WALK: on a strip build, some batches that open a strip draw it and every strip
        // after it; elsewhere set on every 20th batch, and ignored (not drawn from a stream, so
        // that a seed's batches stay as they were).
        bool walk = strip_rows == 0 && b % 20 == 7;
        if (strip_rows != 0) {
            // A strip build: the band, the clear, the planes and the depth test by the strip
            // buffer's rules (contract "The strip buffer"), from the model's open strip; now and
            // then one that breaks them (ERR_STRIP, nothing drawn).
            const gpu_model *mm = model.model();
            const uint32_t strips_n = (static_cast<uint32_t>(fb.h) + strip_rows - 1) / strip_rows;
            const bool opens = mm->open_strip < 0 || clear_forced || (!reset_probe && rs.chance(35));
            const uint32_t k = clear_forced ? reset_strip
                             : opens ? rs.below(strips_n) : static_cast<uint32_t>(mm->open_strip);
            const uint32_t k_first = k * strip_rows;
            const uint32_t k_rows = std::min(strip_rows, static_cast<uint32_t>(fb.h) - k_first);
            uint32_t first = k_first, last = k_first + k_rows - 1;
            if (opens) {
                clear = true;
                planes = 3;
                zclear = zclear || rs.chance(70);
                last = (last == static_cast<uint32_t>(fb.h) - 1 && rs.chance(30)) ? 0xFFFFu : last;
                // (a walk sets up every primitive once a strip: on strips of 1 row, 480 times)
                walk = !clear_forced && !reset_probe && rs.chance(strip_rows >= 4 ? 20 : 4);
            } else if (rs.chance(70)) {
                first = k_first + rs.below(k_rows);
                last = first + rs.below(k_first + k_rows - first);
            }
            const bool whole = first == k_first && last >= k_first + k_rows - 1;
            const bool opens_k = mm->open_strip != static_cast<int64_t>(k);
            const bool zclear_after = (!opens_k && mm->open_strip_zclear) || (zclear && whole);
            ztest = ztest && zclear_after;
            if (!clear_forced && !reset_probe && rs.chance(8)) {  // broken on purpose: one rule or another
                switch (rs.below(3)) {
                case 0:  // rows in two strips (where there are two)
                    last = std::min(last + strip_rows, 0xFFFFu);
                    break;
                case 1:  // opening without clearing all of it
                    clear = false;
                    break;
                default:  // testing depths not cleared
                    ztest = true;
                    zclear = false;
                    break;
                }
            }
            strip = first | (last << GPU_STRIP_LAST_LSB);
            reset_strip = k;
            strips++;
        }
        write(GPU_WIN_REGS + GPU_REG_FB_WRITE_MASK, planes | planes_junk);
        masked += (wmask && planes != 3u) ? 1u : 0u;
        write(GPU_WIN_REGS + GPU_REG_STRIP, strip);
        const uint32_t ctrl = (clear ? GPU_CTRL_CLEAR_MASK : 0) | (swap ? GPU_CTRL_SWAP_MASK : 0)
                            | (ztest ? GPU_CTRL_ZTEST_MASK : 0) | (zclear ? GPU_CTRL_ZCLEAR_MASK : 0)
                            | (dither ? GPU_CTRL_DITHER_MASK : 0) | (walk ? GPU_CTRL_WALK_MASK : 0);
        walks += walk && strip_rows != 0;
        write(GPU_WIN_REGS + GPU_REG_CTRL, ctrl);
        const uint32_t tag = static_cast<uint32_t>(b + 1);
        write(GPU_WIN_REGS + GPU_REG_DOORBELL, tag);

        bool probe_ended = false;  // a small GPU's batch may be done before the RESET lands
        uint32_t done_before = 0;
        if (reset_probe) {
            done_before = sim.read(GPU_REG_DONE_SEQ);
            for (uint32_t i = 0; i < 50 + r.below(20000); i++) {
                sim.tick();
                if (small_caps && !(sim.read(GPU_REG_STATUS) & GPU_STATUS_BUSY_MASK)) {
                    probe_ended = true;  // then it is checked as any batch, below
                    must_clear = false;
                    break;
                }
            }
        }
        if (reset_probe && !probe_ended) {
            write(GPU_WIN_REGS + GPU_REG_RESET, tag);
            sim.tick();
            const uint32_t status = sim.read(GPU_REG_STATUS);
            if ((status & GPU_STATUS_BUSY_MASK) || sim.read(GPU_REG_DONE_SEQ) != done_before) {
                std::printf("random: seed %llu batch %d: RESET left STATUS 0x%x, DONE_SEQ %u (was %u)\n",
                            static_cast<unsigned long long>(seed), b, status, sim.read(GPU_REG_DONE_SEQ), done_before);
                return 1;
            }
            resets++;
            continue;
        }

        if (!sim.wait_done(tag, 50000000)) {
            std::printf("random: seed %llu batch %d: GPU timeout (STATUS 0x%x DONE_SEQ %u ERRORS 0x%x TRIS_IN %u)\n", static_cast<unsigned long long>(seed), b, sim.read(GPU_REG_STATUS), sim.read(GPU_REG_DONE_SEQ), sim.read(GPU_REG_ERRORS), sim.read(GPU_REG_PERF_TRIS_IN));
            return 1;
        }
        std::string diff = model.compare_registers(sim);
        for (const uint32_t reg : {GPU_REG_FB_WRITE_MASK, GPU_REG_STRIP}) {
            if (diff.empty() && sim.read(reg) != gpu_model_read(model.model(), reg)) {
                diff = std::string(reg == GPU_REG_STRIP ? "STRIP" : "FB_WRITE_MASK") + " reads " +
                       std::to_string(sim.read(reg)) + ", the model's " +
                       std::to_string(gpu_model_read(model.model(), reg));
            }
        }
        if (diff.empty()) {
            diff = compare_back_buffer(sim, model, back);
            back_checks++;
        }
        if (diff.empty() && swap) {
            if (!sim.capture_frame(3 * GpuSim::kScanClocks)) {
                diff = std::string("no VGA frame: ") + sim.vga_error();
            } else {
                diff = model.compare_frame(sim.frame_rgb());
                frames++;
            }
        }
        if (diff.empty() && !sim.memory_error().empty()) {
            diff = sim.memory_error();
        }
        if (!diff.empty()) {
            std::printf("random: seed %llu batch %d (vertex family %d, %u prims, CTRL 0x%x, FB_WRITE_MASK %u, STRIP 0x%08x, %llu resets before): %s\n",
                        static_cast<unsigned long long>(seed), b, family, nt, ctrl, planes, strip,
                        static_cast<unsigned long long>(resets), diff.c_str());
            return 1;
        }
        tris += sim.read(GPU_REG_PERF_TRIS_IN);
        shaded += (over_capacity || past) ? 0 : batch_shaded;
        pixels += sim.read(GPU_REG_PERF_PIXELS);
        const uint32_t errors = sim.read(GPU_REG_ERRORS);  // equal to the model's (compared above)
        overflows += (errors & GPU_ERR_COUNT_MASK) != 0;
        index_errors += (errors & GPU_ERR_VTX_INDEX_MASK) != 0;
        strip_refusals += (errors & GPU_ERR_STRIP_MASK) != 0;
    }
    if (overflows < min_overflows) {
        std::printf("random: only %llu batches over the capacities (ERR_COUNT), fewer than the %llu asked for\n",
                    static_cast<unsigned long long>(overflows), static_cast<unsigned long long>(min_overflows));
        return 1;
    }
    if (tris < min_prims) {
        std::printf("random: only %llu primitives checked, fewer than the %llu asked for\n",
                    static_cast<unsigned long long>(tris), static_cast<unsigned long long>(min_prims));
        return 1;
    }
    const uint32_t fb_size = sim.read(GPU_REG_FB_SIZE);  // the RTL's, which the model's has equalled
    if (sim.memory_words_written() + sim.memory_words_read() != 0) {
        // SCANOUT_UNDERFLOWS has equalled the model's 0 after every batch.
        std::printf("random: frames in external memory: %llu native words written, %llu read by the scan-out, no underflow\n",
                    static_cast<unsigned long long>(sim.memory_words_written()),
                    static_cast<unsigned long long>(sim.memory_words_read()));
    }
    if (strip_rows != 0) {
        std::printf("random: strips of %u rows, %llu batches refused (ERR_STRIP), %llu walking the strips after theirs (CTRL.WALK), the frame refusing %u %% of the clocks\n",
                    strip_rows, static_cast<unsigned long long>(strip_refusals),
                    static_cast<unsigned long long>(walks), throttle);
    }
    std::printf("random: seed %llu: VTX_CAP %u TRI_CAP %u FB %ux%u, %d batches (%llu over the capacities, %llu with bad "
                "indices, %llu plane-masked, %llu in strips), %llu primitives (%llu of kind Gouraud), %llu pixels, %llu back buffers, %llu frames, %llu resets: "
                "RTL equals model\n",
                static_cast<unsigned long long>(seed), vcap, tcap, fb_size & 0xFFFFu, fb_size >> 16, batches, static_cast<unsigned long long>(overflows),
                static_cast<unsigned long long>(index_errors), static_cast<unsigned long long>(masked),
                static_cast<unsigned long long>(strips), static_cast<unsigned long long>(tris),
                static_cast<unsigned long long>(shaded),
                static_cast<unsigned long long>(pixels), static_cast<unsigned long long>(back_checks),
                static_cast<unsigned long long>(frames), static_cast<unsigned long long>(resets));
    return 0;
}
