#pragma once
// A work unit is a fresh process: every buffer it fills (the BVH, the per-pixel sums and samples,
// the images) is first-touched page by page, ~20 k page faults for a 512x512 unit, a quarter of
// a 1-spp unit's CPU time on a virtual machine. glibc's malloc backs its large blocks with
// transparent huge pages when the tunable glibc.malloc.hugetlb=1 is set, which glibc reads only
// at process start.
namespace proxyvis {

// Runs the program again (same argv, same executable) with glibc.malloc.hugetlb=1 added to
// GLIBC_TUNABLES, unless that tunable is already set (by this function in the parent, or by the
// user: glibc.malloc.hugetlb=0 turns it off). If exec fails the program simply goes on.
void execWithHugePageMalloc(char** argv);

}  // namespace proxyvis
