// miniaster: runs code_aster command files (.comm / .export). See README.md.
#include "core/MallocHugePages.hpp"
#include "parser/Supervisor.hpp"

int main(int argc, char** argv) {
    ma::reexecWithMallocOnHugePages(argv);
    return ma::supervisorMain(argc, argv);
}
