# tests/soc/soc_lib.sh — sourced by the tests/soc/*.sh scripts after tests/lib.sh: where socsim and
# the soc test programs are (cosim/soc/socsim.mk and tests/soc/tests.mk build them: make soc-test-deps).
#   $socsim              the SoC simulator for the default RAM size (SOCSIM overrides it)
#   $soc_test_dir        the FW_PLATFORM=soc test builds (<scene>.elf, tetra-watchdog-tiny.elf, bus_error.elf)
socsim=${SOCSIM:-$BUILD/socsim-192k/socsim}
soc_test_dir=$BUILD/fw-test-soc
