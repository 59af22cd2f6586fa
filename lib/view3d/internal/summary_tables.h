#pragma once
// The tables of a 3D view page (summary_tables.cpp): verdicts, the four classes and both meshes,
// from the page's check and meshes.
#include <string>

#include "view3d/view3d_html.h"

namespace proxyvis::detail {

// The HTML of the tables, in page order; page.original and page.proxy must be set.
std::string summaryTables(const View3dPage& page);

}  // namespace proxyvis::detail
