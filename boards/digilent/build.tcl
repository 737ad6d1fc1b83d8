# build.tcl: Vivado non-project flow for a Digilent board top — NOT run in this repository (no Vivado
# here); a standard sequence, to be checked by the first user who has Vivado.
# Usage, from the repository root, BOARD basys3 or nexys_a7:
#   SOC_CPU_V=$(.venv/bin/python -c 'import os, pythondata_cpu_vexriscv as p; print(os.path.join(p.data_location, "VexRiscv_FullCfu.v"))') \
#   vivado -mode batch -source boards/digilent/build.tcl -tclargs BOARD [firmware.hex [RAM_BYTES]]
# Output in build/vivado-BOARD/: BOARD_top.bit, the timing and utilisation reports.
set parts [dict create basys3 xc7a35tcpg236-1 nexys_a7 xc7a100tcsg324-1]
set board [lindex $argv 0]
if {![dict exists $parts $board]} { error "build.tcl: BOARD must be one of [dict keys $parts], not '$board'" }
set part [dict get $parts $board]
set top  ${board}_top
set out  build/vivado-$board
file mkdir $out

# The file lists (one path a line, // starts a comment), in compilation order.
proc read_list {f} {
    set paths {}
    foreach line [split [read [open $f]] "\n"] {
        regsub {//.*} $line {} line
        set line [string trim $line]
        if {$line ne ""} { lappend paths $line }
    }
    return $paths
}
set srcs [concat [read_list gpu_rtl/files.f] [list $::env(SOC_CPU_V)] [read_list soc_rtl/files.f] \
             [read_list boards/digilent/files.f] [list boards/$board/$top.v]]
read_verilog -sv $srcs
read_xdc boards/$board/$board.xdc

# Optional: the firmware image (RAM_INIT) and the RAM size (RAM_BYTES) it was linked for.
set synth_args [list -top $top -part $part -include_dirs [pwd]]
if {[llength $argv] >= 2} { lappend synth_args -generic "RAM_INIT=\"[file normalize [lindex $argv 1]]\"" }
if {[llength $argv] >= 3} { lappend synth_args -generic "RAM_BYTES=[lindex $argv 2]" }

synth_design {*}$synth_args
opt_design
place_design
phys_opt_design
route_design
report_utilization -file $out/utilization.rpt
report_timing_summary -file $out/timing_summary.rpt
write_bitstream -force $out/$top.bit
