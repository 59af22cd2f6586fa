#pragma once
// Text helpers of the page writer (html_text.cpp). base64 and jsonForScript are declared in
// view3d_html.h, where the tests reach them; escapeHtml is util/escape_html.h.
#include <cstdint>
#include <string>

namespace proxyvis::detail {

// 1234567 as "1,234,567".
std::string withThousands(uint64_t n);

}  // namespace proxyvis::detail
