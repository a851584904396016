#pragma once
// What a fuzz target asserts beyond "no crash": a broken promise of a parser aborts with a
// line saying which, so libFuzzer keeps the input as a crash like any sanitizer report.
#include <cstdio>
#include <cstdlib>

#define FUZZ_CHECK(condition, what)                                                         \
    do {                                                                                    \
        if (!(condition)) {                                                                 \
            std::fprintf(stderr, "fuzz check failed: %s (%s:%d)\n", what, __FILE__, __LINE__); \
            std::abort();                                                                   \
        }                                                                                   \
    } while (false)
