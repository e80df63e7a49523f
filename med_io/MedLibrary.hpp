#pragma once
// Process start-up of the MED/HDF5 libraries, for the program's main().
namespace ma::med {

// Initialises HDF5 (no exit handler, errors silenced) BEFORE MPI_Init: HDF5's OpenMPI flavour,
// initialised after MPI_Init, ties its shutdown to MPI_Finalize, which then closes every file left
// open and crashed on one whose close had failed (disk full; tests/cli/faults.cpp).
void initialiseBeforeMpi();

}  // namespace ma::med
