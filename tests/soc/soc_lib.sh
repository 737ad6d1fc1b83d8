# tests/soc/soc_lib.sh — sourced by the tests/soc/*.sh scripts after tests/lib.sh: where socsim and
# the soc test programs are (cosim/soc/socsim.mk and tests/soc/tests.mk build them: make soc-test-deps).
#   $socsim              the SoC simulator for the default RAM size (SOCSIM overrides it)
#   $soc_test_dir        the FW_PLATFORM=soc test builds (<scene>.elf, tetra-watchdog-tiny.elf, bus_error.elf)
#   soc_scenes           the scene table's names, in its order
socsim=${SOCSIM:-$BUILD/socsim-192k/socsim}
soc_test_dir=$BUILD/fw-test-soc

soc_scenes() {
    sed -n 's/^SCENE(\([A-Za-z0-9_]*\)[,)].*/\1/p' firmware/scenes/scene_list.h
}
