#!/usr/bin/env bash
# An image larger than the SoC's RAM is refused at build time: tetra linked for SOC_RAM_KIB=16 must
# fail the build with its text, data, bss and stack sizes and the RAM's, and leave no ELF or hex
# behind (so make does not take it as built).
source "$(dirname "$0")/../lib.sh"
need BUILD
work=$(fresh_dir soc-too-big)
# A build tree of its own, with make test's soc objects copied in (timestamps kept: only the link
# and app.c, whose flags name the RAM size, are redone).
mkdir -p "$work/build/firmware-soc" "$work/build/fw-obj-soc"
for objs in "$BUILD"/fw-obj-soc/fixed-*; do
    [ ! -d "$objs" ] || cp -a "$objs" "$work/build/fw-obj-soc/"
done

run_to "$work/small.out" 300 make --no-print-directory -j2 FW_PLATFORM=soc BUILD="$work/build" SCENE=tetra \
    SOC_RAM_KIB=16 "$work/build/firmware-soc/tetra.elf"
[ "$status" -ne 0 ] || fail "the build for 16 KiB of RAM succeeded"
expect_line "error: tetra.elf does not fit the SoC's RAM: text [0-9]+ \+ data [0-9]+ \+ bss [0-9]+ \+ stack [0-9]+ = [0-9]+ bytes .*RAM 16384 bytes \(16 KiB\)" \
    "$work/small.out"
[ ! -e "$work/build/firmware-soc/tetra.elf" ] || fail "the refused ELF was left behind"
[ ! -e "$work/build/firmware-soc/tetra.elf.hex" ] || fail "a hex file was written for the refused ELF"
pass "soc-too-big: $(grep -o 'text [0-9]* + data.*KiB)' "$work/small.out")"
