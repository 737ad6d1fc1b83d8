# host_tb_build.sh, sourced by tests/usb/host.sh and tests/usb/regs.sh: the USB host's sources and
# the build of a bench around one of its tops. Needs BUILD and VERILATOR_RT.
# usb_host_src: the host's files in dependency order, as the SoC's list has them (soc_rtl/files.f:
# the package, then soc_rtl/usb/ with soc_usb.v last, for the register block's bench).
usb_host_src="soc_rtl/soc_pkg.sv $(sed -n -e 's://.*::' -e '/^soc_rtl\/usb\//p' soc_rtl/files.f | tr '\n' ' ')"

# usb_host_bench TOP BENCH: lint TOP under -Wall, then Verilate it at 50 MHz with
# tests/usb/BENCH.cpp and the keyboard model into $BUILD/tests/usb-BENCH/BENCH; prints its path.
usb_host_bench() {
    local top=$1 bench=$2 dir="$BUILD/tests/usb-$2"
    mkdir -p "$dir"
    dir="$(cd "$dir" && pwd)"
    verilator --lint-only -Wall --top-module "$top" soc_rtl/usb/lint.vlt $usb_host_src >&2
    echo "lint: $top clean under -Wall" >&2
    verilator --cc --exe --build -j 1 --assert --x-assign fast --x-initial fast --top-module "$top" \
        -GSYS_HZ=50000000 $usb_host_src "$PWD/tests/usb/$bench.cpp" "$PWD/cosim/usb/usb_kbd_device.cpp" \
        -CFLAGS "-O2 -std=c++17 -I$PWD/cosim/usb -I$PWD/contract -I$PWD/tests/usb" -LDFLAGS "$VERILATOR_RT" \
        --MAKEFLAGS "VM_GLOBAL_FAST= VM_GLOBAL_SLOW=" --Mdir "$dir/obj" -o "$dir/$bench" \
        >"$dir/verilator.log" 2>&1 || { tail -30 "$dir/verilator.log" >&2; return 1; }
    echo "$dir/$bench"
}
