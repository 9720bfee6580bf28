// Placeholder until the batch solve lands: keeps `regio-solve solve` linking
// and answering honestly.
#include "solver/cli/commands.h"

#include <iostream>

namespace regio::cli {

int runSolve(int, char**)
{
    std::cerr << "regio-solve solve: the solver is not built yet\n";
    return kExitFailure;
}

} // namespace regio::cli
