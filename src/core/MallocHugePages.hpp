#pragma once
// glibc's malloc on transparent huge pages (docs/fe.md, "Performance").
//
// The kernel of the target machines gives transparent huge pages only to memory that asks for them
// (THP mode 'madvise'), and glibc's malloc asks only when the tunable glibc.malloc.hugetlb=1 is
// set, which glibc reads once, at start-up. Without it every 4 KB page of the 4 GB of a 2e6-DOF run
// (mesh, MUMPS's factors, fields) costs a page fault: 1.2 million of them, 22 s of system time and
// 36 s of wall time on the VM instead of 23 s. So the program re-executes itself once with the
// tunable added, unless the user's GLIBC_TUNABLES already sets it (either way) or THP is 'never'.
namespace ma {

// Call first in main(): returns only when no re-execution is needed or possible.
void reexecWithMallocOnHugePages(char** argv);

// For the .mess header: "glibc.malloc.hugetlb=1" when malloc uses huge pages, else why not.
const char* mallocHugePagesState();

}  // namespace ma
