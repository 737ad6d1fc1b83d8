# gtkwave -S: print the traces the save file put in the wave window, one "trace: NAME" a line, then quit
# (tests/cosim/waves.sh: what gtkwave itself found of a save file's signals).
set n [gtkwave::getTotalNumTraces]
for {set i 0} {$i < $n} {incr i} { puts "trace: [gtkwave::getTraceNameFromIndex $i]" }
gtkwave::/File/Quit
