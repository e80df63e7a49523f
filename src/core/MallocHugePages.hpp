#pragma once
// Which pages glibc's malloc takes, for the .mess header. miniaster leaves glibc's default (4 KB
// pages; the kernel's THP mode 'madvise' gives huge pages only on request): on the project's VM
// malloc on transparent huge pages (GLIBC_TUNABLES=glibc.malloc.hugetlb=1) made the refined
// ssnv511a run 1.33 times slower on a machine that had been up for hours, although it had made it
// 1.6 times faster on a freshly booted one (docs/fe.md, "Memory"). A user's GLIBC_TUNABLES is
// honoured as given.
namespace ma {

// "glibc.malloc.hugetlb=1 from GLIBC_TUNABLES (...)" or "4 KB pages (glibc's default)".
const char* mallocPagesState();

}  // namespace ma
