// Whether this test program is built with AddressSanitizer (tools/test.sh --sanitize): there it
// runs some 10 to 20 times slower, and a test whose many random cases check numbers, not memory,
// may check fewer of them (the plain build checks them all).
#pragma once

namespace stickslip {

#if defined(__SANITIZE_ADDRESS__)  // g++
inline constexpr bool kSanitizedBuild = true;
#elif defined(__has_feature)  // clang
#if __has_feature(address_sanitizer)
inline constexpr bool kSanitizedBuild = true;
#else
inline constexpr bool kSanitizedBuild = false;
#endif
#else
inline constexpr bool kSanitizedBuild = false;
#endif

}  // namespace stickslip
