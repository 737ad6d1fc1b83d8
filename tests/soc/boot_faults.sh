#!/usr/bin/env bash
# The boot program (bsp/soc/boot, docs/boot.md) on what can be wrong with a board booting from the
# SDRAM, on socsim-sdram with tetra's 2-frame image: each case must stop before the firmware runs
# (no frame), print why with its numbers, show its code on the LEDs and exit with it.
#   - an erased flash (no image):                       0xE2 "no firmware image"
#   - a header with one bit flipped:                    0xE3 "image header corrupt"
#   - a well-formed header whose image does not fit:    0xE3 "image does not fit the SDRAM"
#   - a chip with address pin A11 stuck low:            0xE1 the memory test names address bit 21
#     (row bit 11: rows sit above 9 column bits and the 16-bit word's byte bit, banks above the rows)
#   - the payload with one bit flipped:                 0xE4 "image payload corrupt", after the copy
# and the good image boots (as in suite soc-sdram-scenes, so not repeated here).
#   usage: boot_faults.sh SOCSIM_SDRAM   (the suite passes {socsim-sdram-<RAM>k})
source "$(dirname "$0")/../lib.sh"
need BUILD
socsim=${1:?usage: boot_faults.sh SOCSIM_SDRAM}
boot="$BUILD/soc/boot.elf.hex"
elf="$BUILD/fw-test-soc-sdram/tetra-3f.elf"
need_file "$socsim" "$boot" "$elf.img"
work=$(fresh_dir soc-boot-faults)

# Corrupt copies of the image: a header bit (the load address), a payload bit, and a header re-sealed
# (its CRC made right) that claims more bytes than the SDRAM holds.
python3 - "$elf.img" "$work" <<'PY'
import struct, sys, zlib
img = bytearray(open(sys.argv[1], "rb").read())
out = sys.argv[2]
def save(name, data):
    open(f"{out}/{name}.img", "wb").write(data)
bad = bytearray(img); bad[8] ^= 0x01; save("header-bit", bad)
bad = bytearray(img); bad[32 + (len(img) - 32) // 2] ^= 0x10; save("payload-bit", bad)
bad = bytearray(img)
words = list(struct.unpack_from("<8I", bad))
words[3] = 0x02000004          # a word more than the SDRAM holds from its base
struct.pack_into("<7I", bad, 0, *words[:7])
struct.pack_into("<I", bad, 28, zlib.crc32(bytes(bad[:28])))
save("too-big", bad)
PY

# case NAME CODE LINE [socsim args]: the run ends with CODE, LEDs CODE, LINE in its UART text, no frame.
check_case() {
    local name="$1" code="$2" line="$3"
    shift 3
    run_to "$work/$name.out" 300 "$socsim" --boot "$boot" --frames "$work/$name-frames" \
        --uart-log "$work/$name.uart" --summary "$work/$name.summary" "$@"
    [ "$status" -eq $((code)) ] || fail "$name: socsim ended with status $status, not the boot program's $((code)) (log: $work/$name.out)"
    expect_line "$line" "$work/$name.uart"
    [ "$(summary leds "$work/$name.summary")" = "$(printf '0x%02x' $((code)))" ] ||
        fail "$name: the LEDs show $(summary leds "$work/$name.summary"), not $(printf '0x%02x' $((code)))"
    expect_eq "$(png_count "$work/$name-frames")" 0 "$name: frames drawn"
    ! grep -q '^tetra fw' "$work/$name.uart" || fail "$name: the firmware started (log: $work/$name.uart)"
    echo "$name: $(grep -m1 'FAILED' "$work/$name.uart")"
}

check_case erased 0xE2 '^boot: FAILED: no firmware image \(wrong magic\) at flash 0x00400000: magic 0xffffffff'
check_case header-bit 0xE3 '^boot: FAILED: image header corrupt' --fw "$elf" --flash "$work/header-bit.img"
check_case too-big 0xE3 '^boot: FAILED: image does not fit the SDRAM .* bytes 33554436' --fw "$elf" --flash "$work/too-big.img"
check_case a11-stuck 0xE1 '^boot: FAILED: the SDRAM does not work' --fw "$elf" --sdram-fault-a 11
expect_line '^boot: memtest: address bus FAILED .*address bit 21' "$work/a11-stuck.uart"
check_case payload-bit 0xE4 '^boot: FAILED: image payload corrupt \(CRC mismatch after the copy\)' --fw "$elf" --flash "$work/payload-bit.img"

# socsim's own setup failures end with its message and status 1 and a summary naming them (a run
# that failed before the chips were made once crashed writing the summary): a flash file that does
# not exist, and a frames directory that cannot be made.
for bad in "--flash $work/missing.img" "--frames /dev/null/frames"; do
    # shellcheck disable=SC2086  # $bad: an option and its value
    run_to "$work/setup.out" 60 "$socsim" --boot "$boot" --summary "$work/setup.summary" $bad
    expect_status 1 "socsim $bad (log: $work/setup.out)"
    [ "$(summary error "$work/setup.summary")" = setup ] || fail "socsim $bad: the summary's error is not setup"
done
pass "soc-boot-faults: an erased flash, a corrupt header, an image too big for the SDRAM, A11 stuck low (address bit 21) and a corrupt payload each stop the boot with its message, LEDs and exit code, no frame drawn; socsim's setup errors (no flash file, no frames directory) end with status 1"
