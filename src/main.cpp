// miniaster: runs code_aster command files (.comm / .export). See README.md.
#include "parser/Supervisor.hpp"

int main(int argc, char** argv) { return ma::supervisorMain(argc, argv); }
