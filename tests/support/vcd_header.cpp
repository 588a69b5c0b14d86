// Minimal VCD reading for tests (see vcd_header.h).
#include "vcd_header.h"

#include <fstream>
#include <sstream>
#include <stdexcept>

namespace ncinterp::test {

std::map<std::string, int> vcd_signals(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open");
  std::map<std::string, int> vars;
  std::vector<std::string> scopes;
  std::string tok;
  while (in >> tok) {
    if (tok == "$scope") {
      std::string kind, name;
      in >> kind >> name;
      scopes.push_back(name);
    } else if (tok == "$upscope") {
      if (!scopes.empty()) scopes.pop_back();
    } else if (tok == "$var") {
      std::string kind, id, name;
      int width = 0;
      in >> kind >> width >> id >> name;
      std::string full;
      for (const std::string& s : scopes) full += s + ".";
      vars[full + name] = width;
    } else if (tok == "$enddefinitions") {
      break;
    }
  }
  return vars;
}

std::vector<uint64_t> vcd_times(const std::string& path) {
  std::ifstream in(path);
  std::vector<uint64_t> times;
  std::string line;
  while (std::getline(in, line))
    if (line.size() > 1 && line[0] == '#') times.push_back(std::stoull(line.substr(1)));
  return times;
}

}  // namespace ncinterp::test
