// tests/boards/crossings.sh's fixture (synth/ecp5_bitstream.py --files)
tests/boards/crossings/xdemo.v
