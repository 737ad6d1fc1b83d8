#!/usr/bin/env bash
# The boot image (docs/boot.md): bsp/soc/mkimage.py writes it from an ELF with a gap between its
# segments and a .bss; tests/boot/image_test.c reads it with the boot program's own checks
# (bsp/soc/boot/boot_image.c) — separate code on each side — and finds the fields and the payload's
# CRC as written, then each corrupt or misplaced header refused with the status the boot program
# reports (erased flash, bad magic, header CRC, layout, outside the SDRAM, wrapping, entry outside,
# a payload bit). mkimage refuses an ELF that does not fit the memory and an entry outside the
# payload, with the numbers.
source "$(dirname "$0")/../lib.sh"
need BUILD
work=$(fresh_dir boot-image)
base=0x40000000; mem=0x02000000

# Twice: with the firmware's CRC (a nibble table) and the boot program's (-DCRC32_SLICE_TABLES=1:
# four tables, a word at a time; image_test also holds it to a bit-by-bit CRC at every alignment).
for table in 0 1; do
    run_to "$work/build-$table.log" 120 gcc -std=c11 -O2 -Wall -Wextra -Werror -DCRC32_SLICE_TABLES=$table -Icontract \
        -Ifirmware -Ibsp/soc/boot tests/boot/image_test.c bsp/soc/boot/boot_image.c firmware/model/crc32.c \
        -o "$work/image_test-$table"
    expect_status 0 "building the boot image's host test (log: $work/build-$table.log)"
done

# Text 0x1000 bytes, a 0x1F0-byte gap, data 0x2A bytes (padded to a word), bss 0x400: the payload is
# 0x1000 + 0x1F0 + 0x2C = 0x121C bytes, the entry 0x40 into the text.
python3 tests/boot/make_elf.py "$work/prog.elf" $base 0x40 0x1000 0x1F0 0x2A 0x400
run_to "$work/mkimage.log" 30 python3 bsp/soc/mkimage.py "$work/prog.elf" "$work/prog.img" --mem-base $base --mem-bytes $mem
expect_status 0 "mkimage on the test ELF (log: $work/mkimage.log)"
for table in 0 1; do
    run_to "$work/out-$table" 30 "$work/image_test-$table" "$work/prog.img" $base $mem $base 0x121C $((base + 0x40))
    expect_status 0 "the boot image's checks, slice tables $table (log: $work/out-$table)"
    last=$(tail -n 1 "$work/out-$table")
    [[ "$last" =~ ^image_test:\ ok\ ([0-9]+)\ cases$ ]] || fail "the last line is '$last' (log: $work/out-$table)"
done
cases=${BASH_REMATCH[1]}

# Refusals: the .bss past a memory of 0x1400 bytes; an entry outside the payload.
run_to "$work/small.log" 30 python3 bsp/soc/mkimage.py "$work/prog.elf" "$work/small.img" --mem-base $base --mem-bytes 0x1400
expect_status 1 "mkimage must refuse an ELF whose .bss passes the memory's end (log: $work/small.log)"
grep -q "outside the memory 0x40000000..0x40001400" "$work/small.log" || fail "mkimage's refusal does not give the memory's range (log: $work/small.log)"
[ ! -e "$work/small.img" ] || fail "mkimage wrote an image it refused"
python3 tests/boot/make_elf.py "$work/far.elf" $base 0x2000 0x1000 0 0x10 0
run_to "$work/far.log" 30 python3 bsp/soc/mkimage.py "$work/far.elf" "$work/far.img" --mem-base $base --mem-bytes $mem
expect_status 1 "mkimage must refuse an entry outside the payload (log: $work/far.log)"
grep -q "is not a word of the payload" "$work/far.log" || fail "mkimage's refusal does not name the entry (log: $work/far.log)"
pass "boot-image: mkimage's image read back by the boot program's checks ($cases cases, with either CRC table: the fields and payload CRC as written, every corrupt or misplaced header refused with its status); mkimage refuses a too-large ELF and a stray entry"
