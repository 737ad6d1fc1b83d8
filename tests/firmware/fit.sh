#!/usr/bin/env bash
# Firmware that fits on a chip (issue #9): every scene's one-scene build (FW_SCENE_SET=one, under
# $BUILD/fw-size) within its target — the default scene's image (text + data + bss + stack) in
# 64 KiB, every other scene's in 192 KiB — with the stack the chip's BSP reserves
# (FW_STACK_BYTES, firmware.mk) above the deepest call chain found in the disassembly. Also: a
# one-scene ELF links no other scene, and no fixed-point build links soft-float arithmetic or
# printf's float conversions.
#
# The images are built with the qemu_virt toolchain flags: the code a soc build has, up to the
# BSP (which has no semihosting and no QEMU test device, so nothing here runs them).
source "$(dirname "$0")/../lib.sh"
need BUILD
dir="$BUILD/fw-size"
scenes=$(sed -n 's/^SCENE(\([A-Za-z0-9_]*\)[,)].*/\1/p' firmware/scenes/scene_list.h)
for s in $scenes; do
    need_file "$dir/$s.elf"
done
need_file "$dir/all-tetra.elf"
NM=${NM:-riscv64-unknown-elf-nm}
work=$(fresh_dir fw-fit)

# A one-scene build references no other scene's descriptor or code.
for s in $scenes; do
    "$NM" "$dir/$s.elf" > "$work/$s.syms"
    for o in $scenes; do
        [ "$o" = "$s" ] && continue
        if grep -qE " scene_${o}_desc$| ${o}_init$" "$work/$s.syms"; then
            fail "$s.elf links scene $o"
        fi
    done
    grep -qE " scene_${s}_desc$" "$work/$s.syms" || fail "$s.elf lacks its own scene"
    # Fixed point: no soft-float routines, no float printf (picolibc's integer printf only).
    if grep -qE " (__adddf3|__subdf3|__muldf3|__divdf3|__addsf3|__subsf3|__mulsf3|__divsf3|__floatsidf|__fixdfsi|__extendsfdf2|__truncdfsf2|__d_vfprintf|__dtoa_engine|__ftoa_engine)$" "$work/$s.syms"; then
        fail "$s.elf (fixed point) links floating-point code: $(grep -oE '(__[a-z]+[sd]f[0-9]?|__d_vfprintf|__[df]toa_engine)$' "$work/$s.syms" | tr '\n' ' ')"
    fi
done

STACK_BYTES=${FW_STACK_BYTES:-4096}  # firmware.mk's default
status=0
SIZE=${SIZE:-riscv64-unknown-elf-size} STACK_BYTES=$STACK_BYTES DEFAULT_SCENE=tetra \
    bash firmware/tools/fw_size.sh --check "$dir" $scenes > "$work/table.md" || status=$?
cat "$work/table.md"
[ "$status" = 0 ] || fail "a scene's image exceeds its target (table above)"
pass "fit: every scene's one-scene image within its target, stack reserve $STACK_BYTES bytes above the deepest chain"
