// dv/coverage/vl_cov_main.cpp - main() of the Verilated benches built with
// --coverage for make rtl-coverage (tests/cov/rtl-coverage.sh): the loop of
// Verilator's own --main, then the coverage counters written to the file
// named by +covfile=FILE (default coverage.dat), which verilator_coverage
// merges.  Verilator 5.006's --binary main writes no coverage file.
#include "verilated.h"
#include "verilated_cov.h"

#include <cstring>
#include <memory>
#include <string>

#include "Vtb_raster.h"   // the whole-pipeline bench, the one make rtl-coverage builds

int main(int argc, char **argv)
{
    const std::unique_ptr<VerilatedContext> contextp{ new VerilatedContext };
    contextp->commandArgs(argc, argv);
    std::string file = "coverage.dat";
    for (int i = 1; i < argc; i++)
        if (std::strncmp(argv[i], "+covfile=", 9) == 0)
            file = argv[i] + 9;
    const std::unique_ptr<Vtb_raster> topp{ new Vtb_raster{ contextp.get() } };
    while (!contextp->gotFinish()) {
        topp->eval();
        if (!topp->eventsPending())
            break;
        contextp->time(topp->nextTimeSlot());
    }
    topp->final();
    contextp->coveragep()->write(file.c_str());
    return 0;
}
