#!/usr/bin/env bash
# fw_size.sh — `make fw-size`: the memory of every scene's firmware image, as a Markdown table.
#
#   fw_size.sh [--check] DIR SCENE...
#
# DIR holds <scene>.elf (the one-scene build, FW_SCENE_SET=one, without line emulation,
# FW_WITH_LINE_EMULATION=0: what a chip whose GPU draws lines runs) for every SCENE,
# <scene>-emul.elf (the same with line emulation, whose frame needs the emulated wireframe's columns:
# shown when present, not checked), <scene>-nowire.elf (the same without the wireframe, FW_WITH_WIREFRAME=0, whose frame needs only
# the filled columns: shown when present, not checked) and all-<scene>.elf (the all-scene build of
# the default scene, for comparison). Per image:
# text (.init .text .rodata ...: every allocated read-only section), data (.data .sdata, which a
# RAM-only chip holds once: the image is loaded into RAM), bss (.bss .sbss .tbss, without the
# linker script's own .stack/.heap reservations), stack (STACK_BYTES, what the chip's BSP
# reserves), total = text + data + bss + stack, against the target: TARGET_DEFAULT bytes for
# DEFAULT_SCENE, TARGET_OTHER for every other scene. The all-scene row has no target.
#
# A "stack measured" column gives the deepest call chain's frames found by
# firmware/tools/stack_depth.py in the disassembly (when python3 is there): the reserve must
# exceed it.
#
# --check: exit 1 if a one-scene image exceeds its target (tests/firmware/fit.sh).
#
# Environment: SIZE, NM, OBJDUMP (the cross binutils), STACK_BYTES, DEFAULT_SCENE,
# TARGET_DEFAULT, TARGET_OTHER, PLATFORM (printed).
set -u

check=0
if [ "${1:-}" = "--check" ]; then
    check=1
    shift
fi
dir=$1
shift
SIZE=${SIZE:-riscv64-unknown-elf-size}
OBJDUMP=${OBJDUMP:-riscv64-unknown-elf-objdump}
STACK_BYTES=${STACK_BYTES:-8192}
DEFAULT_SCENE=${DEFAULT_SCENE:-tetra}
TARGET_DEFAULT=${TARGET_DEFAULT:-65536}
TARGET_OTHER=${TARGET_OTHER:-196608}
PLATFORM=${PLATFORM:-qemu_virt}
here=$(cd "$(dirname "$0")" && pwd)

# text data bss of an ELF, from the section table (size -A): by section name.
sections() {
    "$SIZE" -A "$1" | awk '
        $1 ~ /^\.(init|text|rodata|srodata|fini|preinit_array|init_array|fini_array|eh_frame)/ { t += $2 }
        $1 ~ /^\.(data|sdata|tdata)/ { d += $2 }
        $1 ~ /^\.(bss|sbss|tbss)$/ { b += $2 }
        END { printf "%d %d %d\n", t, d, b }'
}

kib() {
    awk -v b="$1" 'BEGIN { printf "%.1f", b / 1024 }'
}

stack_measured() {
    if command -v python3 >/dev/null 2>&1; then
        python3 "$here/stack_depth.py" --objdump "$OBJDUMP" "$1" 2>/dev/null | awk '{print $1}'
    fi
}

fail=0
echo "Memory per scene ($PLATFORM toolchain flags, fixed-point backend; stack reserved: $STACK_BYTES bytes)"
echo
echo "| build | text | data | bss | stack | total | KiB | target | fits | stack measured |"
echo "|---|---:|---:|---:|---:|---:|---:|---:|---|---:|"
row() {
    local name=$1 elf=$2 target=$3
    local t d b total verdict meas
    if [ ! -f "$elf" ]; then
        echo "fw_size: $elf missing (make fw-size-deps)" >&2
        fail=1
        return
    fi
    read -r t d b < <(sections "$elf")
    total=$((t + d + b + STACK_BYTES))
    meas=$(stack_measured "$elf")
    if [ -z "$target" ]; then
        verdict="—"
        target_s="—"
    else
        target_s="$((target / 1024)) KiB"
        if [ "$total" -le "$target" ]; then
            verdict="yes"
        else
            verdict="**no** (+$((total - target)))"
            fail=1
        fi
    fi
    if [ -n "$meas" ] && [ "$meas" -ge "$STACK_BYTES" ]; then
        meas="**$meas** (over the reserve)"
        fail=1
    fi
    echo "| $name | $t | $d | $b | $STACK_BYTES | $total | $(kib "$total") | $target_s | $verdict | ${meas:-?} |"
}
for s in "$@"; do
    if [ "$s" = "$DEFAULT_SCENE" ]; then
        target=$TARGET_DEFAULT
    else
        target=$TARGET_OTHER
    fi
    row "$s" "$dir/$s.elf" "$target"
    if [ -f "$dir/$s-emul.elf" ]; then
        keep=$fail
        row "$s, line emulation" "$dir/$s-emul.elf" "$target"
        fail=$keep  # shown for comparison
    fi
    if [ -f "$dir/$s-nowire.elf" ]; then
        keep=$fail
        row "$s, no wireframe" "$dir/$s-nowire.elf" "$target"
        fail=$keep  # shown for comparison: the build with every feature is the one checked
    fi
done
row "all scenes (boot $DEFAULT_SCENE)" "$dir/all-$DEFAULT_SCENE.elf" ""
if [ "$check" = 1 ] && [ "$fail" != 0 ]; then
    exit 1
fi
exit 0
