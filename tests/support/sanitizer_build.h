#pragma once
// Whether this test executable is built with AddressSanitizer. GCC defines
// __SANITIZE_ADDRESS__; clang 14 (the sanitizer build's compiler) does not, it answers
// __has_feature(address_sanitizer) instead. Tests that scale their work down under the
// sanitizers ask here, so both compilers take the same decision.
namespace proxyvis::test {

#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kSanitizerBuild = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr bool kSanitizerBuild = true;
#else
inline constexpr bool kSanitizerBuild = false;
#endif
#else
inline constexpr bool kSanitizerBuild = false;
#endif

}  // namespace proxyvis::test
