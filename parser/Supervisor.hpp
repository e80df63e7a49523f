#pragma once
// The supervisor: reads the command line (`run case.export` | `run case.comm --mesh m.med`),
// sets up the logical units, runs the .comm file in embedded CPython, writes .mess/.resu and
// returns the exit status (0 OK, 2 NOOK, 1 error).
namespace ma {

int supervisorMain(int argc, char** argv);

}  // namespace ma
