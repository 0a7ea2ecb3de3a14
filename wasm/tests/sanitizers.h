// Whether this test binary runs under AddressSanitizer (with UndefinedBehaviorSanitizer: the
// Debug build of scripts/test-sanitize.sh, build/native-asan), where a solve runs about 20 times slower.
// The slowest suites draw fewer targets there (sanitized_count) and assert the same things.
#pragma once

#if defined(__SANITIZE_ADDRESS__)
#define IK_UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define IK_UNDER_ASAN 1
#endif
#endif

namespace ik::test {

#ifdef IK_UNDER_ASAN
inline constexpr bool kUnderSanitizers = true;
#else
inline constexpr bool kUnderSanitizers = false;
#endif

// `full` (the count a suite was written for), or `sanitized` under the sanitizers.
constexpr int sanitized_count(int full, int sanitized) { return kUnderSanitizers ? sanitized : full; }

}  // namespace ik::test
