// gpusim: host tools around the Verilated GPU.
//   gpusim cosim ...   run firmware in QEMU against the RTL (cosim_run.cpp)
//   gpusim random ...  seeded random batches, RTL against the golden model (rtl_check.cpp)
//   gpusim raster ...  a primitive list through RTL and model, to files (raster_run.cpp)
//   gpusim list-roundtrip ...  the primitive-list writer against its parser (list_roundtrip.cpp)
//   gpusim scanout-underflow ...  the display when the frames' memory stalls (scanout_check.cpp)
#include <cstdio>
#include <cstring>

#include "verilated.h"

int cosim_main(int argc, char **argv);
int rtl_check_main(int argc, char **argv);
int raster_main(int argc, char **argv);
int list_roundtrip_main(int argc, char **argv);
int scanout_underflow_main(int argc, char **argv);

int main(int argc, char **argv)
{
    Verilated::commandArgs(1, argv);
    if (argc >= 2 && std::strcmp(argv[1], "cosim") == 0) {
        return cosim_main(argc - 2, argv + 2);
    }
    if (argc >= 2 && std::strcmp(argv[1], "random") == 0) {
        return rtl_check_main(argc - 2, argv + 2);
    }
    if (argc >= 2 && std::strcmp(argv[1], "raster") == 0) {
        return raster_main(argc - 2, argv + 2);
    }
    if (argc >= 2 && std::strcmp(argv[1], "list-roundtrip") == 0) {
        return list_roundtrip_main(argc - 2, argv + 2);
    }
    if (argc >= 2 && std::strcmp(argv[1], "scanout-underflow") == 0) {
        return scanout_underflow_main(argc - 2, argv + 2);
    }
    std::fprintf(stderr, "usage: gpusim cosim|random|raster|list-roundtrip|scanout-underflow [options]   (see README.md)\n");
    return 2;
}
