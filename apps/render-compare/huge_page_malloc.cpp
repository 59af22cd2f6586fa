#include "huge_page_malloc.h"

#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <string>

namespace proxyvis {

void execWithHugePageMalloc(char** argv) {
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  if (tunables && std::strstr(tunables, "glibc.malloc.hugetlb")) return;
  const std::string value = tunables && *tunables
                                ? std::string(tunables) + ":glibc.malloc.hugetlb=1"
                                : std::string("glibc.malloc.hugetlb=1");
  if (setenv("GLIBC_TUNABLES", value.c_str(), 1) != 0) return;
  execv("/proc/self/exe", argv);  // returns only on failure: go on with 4 KiB pages
}

}  // namespace proxyvis
