// Tape files: .tape holds the 8-bit frames as punched; any other extension is plain text
// (.nc, .ngc, .txt) that gets parity added on load. Writing is atomic (sw/host/common).
#include <cstdio>
#include <fstream>
#include <iterator>
#include <stdexcept>

#include "atomic_file.h"
#include "tape.h"

namespace ncinterp::tape {

bool is_frame_file(const std::string& path) {
  const std::string ext = ".tape";
  return path.size() >= ext.size() && path.compare(path.size() - ext.size(), ext.size(), ext) == 0;
}

std::vector<uint8_t> load_frames(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot open for reading");
  std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(in)),
                             std::istreambuf_iterator<char>());
  if (in.bad()) throw std::runtime_error(path + ": read error");
  if (is_frame_file(path)) return bytes;
  for (size_t k = 0; k < bytes.size(); ++k) {
    if (bytes[k] > 127) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "0x%02X", bytes[k]);
      throw std::runtime_error(path + ": offset " + std::to_string(k) + ": byte " + hex +
                               " is not 7-bit ASCII (a plain-text tape must be ASCII; "
                               "frames with parity belong in a .tape file)");
    }
  }
  return add_parity(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

void write_tape_file(const std::string& path, const Program& program, const Format& format) {
  const std::string text = format_program(program, format);  // validates before any I/O
  write_file_atomically(path, is_frame_file(path) ? add_parity(text)
                                                  : std::vector<uint8_t>(text.begin(), text.end()));
}

}  // namespace ncinterp::tape
