// libsystemc.so refers to sc_main (its own main() would call it), so every executable that
// links SystemC must define one. ncinterp's executables have their own main() and drive
// SystemC directly (sc_start from run_play), so this sc_main is never the entry point; if
// anything ever calls it, it says so and fails.
#include <cstdio>

extern "C" int sc_main(int, char**) {
  std::fprintf(stderr, "ncinterp: sc_main is not an entry point of this program\n");
  return 1;
}
