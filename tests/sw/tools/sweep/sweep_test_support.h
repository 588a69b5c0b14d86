// Shared by the sweep tests: paths of the examples, fixtures and captured logs (scratch
// directories and the command line come from tests/support).
#pragma once
#include <string>

namespace ncinterp::sweep::test {

std::string example(const std::string& name);   // examples/<name>
std::string fixture(const std::string& name);   // tests/sw/tools/sweep/fixtures/<name>
std::string log_snippet(const std::string& name);  // the content of tests/sw/tools/sweep/logs/<name>

}  // namespace ncinterp::sweep::test
