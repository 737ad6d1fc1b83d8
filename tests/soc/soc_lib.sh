# tests/soc/soc_lib.sh — sourced by the tests/soc/*.sh scripts after tests/lib.sh: where socsim and
# the soc test programs are (cosim/soc/socsim.mk and tests/soc/tests.mk build them: make soc-test-deps).
#   $socsim              the SoC simulator for the default RAM size (SOCSIM overrides it)
#   $soc_test_dir        the FW_PLATFORM=soc test builds (<scene>.elf, tetra-watchdog-tiny.elf, bus_error.elf)
socsim=${SOCSIM:-$BUILD/socsim-192k/socsim}
soc_test_dir=$BUILD/fw-test-soc
# The host build's options for the GPU of the systems with the frames in the SDRAM
# (socsim-sdram-dram, socsim-ulx3s-sdram-dram in mk/builds.toml: 640x480, depth, Gouraud).
dram_host_frame=(--frame 640x480 --zbuf --gouraud)
#
#   soc_test PROGRAM NAME          $elf: the soc test build PROGRAM (it and socsim must exist);
#                                  $work: the empty run folder NAME (fresh_dir)
#   run_socsim TIMEOUT ARG...      socsim on $elf, frames to $work/frames, UART to $work/uart.log,
#                                  output to $work/out, with ARG...; sets $status (run_to)
#   frame_lines UART_LOG           the firmware's frame lines without their instruction counts
#   each_scene JOBS FUNCTION SCENE...
#                                  FUNCTION SCENE for every scene in the background, JOBS at a time;
#                                  fails naming a scene whose FUNCTION failed
#   total_frames SUMMARY SCENE...  the frames of all the scenes' summaries (SUMMARY: the path with
#                                  % for the scene)

soc_test() {
    elf="$soc_test_dir/$1.elf"
    need_file "$socsim" "$elf.hex"
    work=$(fresh_dir "$2")
}

run_socsim() {
    local limit="$1"
    shift
    run_to "$work/out" "$limit" "$socsim" --fw "$elf" --frames "$work/frames" --uart-log "$work/uart.log" "$@"
}

frame_lines() {
    # a line the end of a run cut short (--stop-frames) before its counts is left out
    { grep '^frame .* | fw instr' "$1" || true; } | sed 's/ | fw instr.*//'
}

each_scene() {
    local jobs="$1" fn="$2" s i pids=() names=()
    shift 2
    for s in "$@"; do
        if [ "${#pids[@]}" -ge "$jobs" ]; then
            wait "${pids[0]}" || fail "scene ${names[0]} (see above)"
            pids=("${pids[@]:1}")
            names=("${names[@]:1}")
        fi
        "$fn" "$s" &
        pids+=($!)
        names+=("$s")
    done
    for i in "${!pids[@]}"; do
        wait "${pids[$i]}" || fail "scene ${names[$i]} (see above)"
    done
}

total_frames() {
    local path="$1" s total=0 n
    shift
    for s in "$@"; do
        n=$(summary frames "${path//%/$s}")
        total=$((total + n))
    done
    echo "$total"
}
