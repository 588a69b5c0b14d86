// What every fuzz target shares: the libFuzzer entry point it defines, and how it reports a
// finding.
// Idea: a target is one function, LLVMFuzzerTestOneInput. The clang build links it with
// libFuzzer (-fsanitize=fuzzer, scripts/fuzz.sh); the normal build links it with
// replay_main.cpp, which runs the checked-in corpus through it under ctest. A finding
// aborts the process in both: libFuzzer saves the input, ctest reports the test as failed.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

namespace ncinterp::fuzz {

// Prints "FUZZ FINDING: what" to stderr and aborts (libFuzzer saves the input as a crash).
[[noreturn]] void fail(const std::string& what);

// A 64-bit hash of the input (FNV-1a): options chosen per input stay reproducible.
uint64_t input_hash(const uint8_t* data, size_t size);

// True when NCINTERP_FUZZ_INJECT names this fault: a bug planted on purpose, so a ctest can
// show that the target's check finds it (tests/fuzz/CMakeLists.txt, fuzz.injected.*).
bool injected(const char* fault);

}  // namespace ncinterp::fuzz
