// interp_pkg_gen: writes rtl/0_interp_pkg.sv, the SystemVerilog package of the interpolator's
// contracts (motion codes, the G and M codes it accepts, error codes, tape characters, the
// board's serial link) and the block record's typedef macro, from the tape library's X-macro
// lists tape_motions.def, tape_codes.def, tape_errors.def, tape_chars.def, board_link.def and
// block_record.def.
// Idea: the C++ side expands the same .def files at compile time, so the RTL and the C++
// models cannot disagree on a code. The package is checked in (the RTL flows read it as a
// plain file); `interp_pkg_gen --check FILE` tells whether FILE is what this program writes,
// and a test runs it on rtl/0_interp_pkg.sv.
// Usage: interp_pkg_gen OUT.sv | interp_pkg_gen --check PKG.sv
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

#include "atomic_file.h"
#include "feed_override.h"
#include "operator_panel.h"

namespace {

struct Entry {
  const char* name;
  unsigned value;
  std::string comment;
};

const Entry kMotions[] = {
#define TAPE_MOTION(name, code, word) {#name, code, word},
#include "tape_motions.def"
#undef TAPE_MOTION
};

// The G and M codes besides the motions, by letter and kind (tape_codes.def).
struct Code {
  char letter;
  unsigned number;
  const char* kind;
  const char* meaning;
};
const Code kCodes[] = {
#define TAPE_CODE(letter, number, kind, meaning) {#letter[0], number, #kind, meaning},
#include "tape_codes.def"
#undef TAPE_CODE
};

// The board's serial link (board_link.def). Each list expands one kind of its lines.
#define BOARD_LINK_BYTE(name, byte, meaning) {#name, byte, meaning},
const Entry kLinkBytes[] = {
#include "board_link.def"
};
#define BOARD_LINK_COUNT(name, value, meaning) {#name, value, meaning},
const Entry kLinkCounts[] = {
#include "board_link.def"
};
#define BOARD_REALTIME(name, byte, key, meaning) {#name, byte, std::string("key '") + key + "': " + meaning},
const Entry kRealtime[] = {
#include "board_link.def"
};
#define BOARD_ERROR(name, code, message) {#name, code, message},
const Entry kBoardErrors[] = {
#include "board_link.def"
};
#define BOARD_STATUS(name, letter, meaning) {#name, static_cast<unsigned>(letter), meaning},
const Entry kStatusKinds[] = {
#include "board_link.def"
};
#define BOARD_STATUS_DIGITS(block, field) block +
constexpr unsigned kStatusBlockDigits =
#include "board_link.def"
    0;
#define BOARD_STATUS_DIGITS(block, field) field +
constexpr unsigned kStatusDigits =
#include "board_link.def"
    0;

const Entry kErrors[] = {
#define TAPE_ERROR(name, code, message) {#name, code, message},
#include "tape_errors.def"
#undef TAPE_ERROR
};

std::string char_comment(char c) {
  if (c >= 0x21 && c < 0x7f) return std::string("'") + c + "'";
  switch (c) {
    case '\0': return "NUL";
    case '\n': return "LF";
    case '\r': return "CR";
    case ' ': return "space";
    default: return "";
  }
}

const Entry kChars[] = {
#define TAPE_CHAR(name, character) \
  {#name, static_cast<unsigned>(static_cast<unsigned char>(character)), char_comment(character)},
#include "tape_chars.def"
#undef TAPE_CHAR
};

template <size_t N>
unsigned bits_for(const Entry (&entries)[N]) {
  unsigned largest = 0, bits = 1;
  for (const Entry& e : entries) largest = e.value > largest ? e.value : largest;
  while ((largest >> bits) != 0) ++bits;
  return bits;
}

std::string literal(unsigned bits, unsigned value, bool hex) {
  char buf[32];
  std::snprintf(buf, sizeof buf, hex ? "%u'h%02x" : "%u'd%u", bits, value);
  return buf;
}

// One aligned line per entry: enum items ("Name = literal," and no comma after the last)
// when `type` is empty, else localparams of that type.
template <size_t N>
void items(std::ostream& out, const Entry (&entries)[N], const std::string& prefix, unsigned bits,
           bool hex, const std::string& type) {
  size_t name_width = 0, value_width = 0;
  for (const Entry& e : entries) {
    name_width = std::max(name_width, prefix.size() + std::string(e.name).size());
    value_width = std::max(value_width, literal(bits, e.value, hex).size() + 1);
  }
  for (size_t i = 0; i < N; ++i) {
    const Entry& e = entries[i];
    std::string name = prefix + e.name;
    name.resize(name_width, ' ');
    std::string value = literal(bits, e.value, hex) + (!type.empty() ? ";" : i + 1 < N ? "," : "");
    std::string line = (type.empty() ? "    " : "  localparam " + type + " ") + name + " = " + value;
    if (!e.comment.empty()) line += std::string(value_width - value.size(), ' ') + "  // " + e.comment;
    out << line << "\n";
  }
}

// A function of the package: whether a G or M code (<= 99: 7 bits) is one of `numbers`.
// A function true for the listed numbers. It compares with literals, not with the enum's
// names: Yosys 0.23 does not resolve a package's enum names inside a package function
// inlined into a module.
void code_function(std::ostream& out, const std::string& name, const std::string& what,
                   const std::vector<std::pair<unsigned, std::string>>& numbers,
                   const std::string& arg = "code", unsigned width = 7,
                   const std::string& width_name = "6") {
  out << "  // " << what << "\n"
      << "  function automatic logic " << name << "(input logic [" << width_name << ":0] " << arg
      << ");\n"
      << "    " << name << " = ";
  for (size_t i = 0; i < numbers.size(); ++i)
    out << (i ? "\n" + std::string(name.size() + 7, ' ') + "|| " : "") << arg << " == " << width
        << "'d" << numbers[i].first;
  out << ";\n  endfunction\n";
}

std::vector<std::pair<unsigned, std::string>> codes(char letter, const std::string& kind) {
  std::vector<std::pair<unsigned, std::string>> out;
  for (const Code& c : kCodes)
    if (c.letter == letter && c.kind == kind) out.emplace_back(c.number, c.meaning);
  return out;
}

// The block record (block_record.def): name, packed range, meaning.
struct Field {
  const char* name;
  const char* range;
  const char* meaning;
};
const Field kBlockFields[] = {
#define BLOCK_FIELD(name, range, meaning) {#name, range, meaning},
#include "block_record.def"
#undef BLOCK_FIELD
};

// `INTERP_BLOCK_T: the typedef of block_t, written as a macro after the package. A macro,
// not an `include of a header: every tool that reads rtl/*.sv (or the package first, as
// every flow of the project does) then has it, with no include path to set.
void block_record_macro(std::ostream& out) {
  size_t range_width = 0;
  for (const Field& f : kBlockFields) range_width = std::max(range_width, std::string(f.range).size());
  out << "\n"
         "// block_t, the decoded block (sw/host/tape/block_record.def), declared inside a module\n"
         "// with `INTERP_BLOCK_T: its widths are the module's IncWidth, SeqWidth, StepWidth, KWidth\n"
         "// and IterWidth. Fields, most significant first:\n";
  for (const Field& f : kBlockFields) out << "//   " << f.name << ": " << f.meaning << "\n";
  out << "`define INTERP_BLOCK_T \\\n"
         "  typedef struct packed { \\\n";
  for (const Field& f : kBlockFields) {
    std::string range = f.range;
    range.resize(range_width, ' ');
    out << "    logic " << range << " " << f.name << "; \\\n";
  }
  out << "  } block_t;\n";
}

std::string package(const std::string& tape_dir) {
  const unsigned motion_bits = bits_for(kMotions), error_bits = bits_for(kErrors);
  std::ostringstream out;
  out << "// interp_pkg: the interpolator's contracts for the RTL: motion codes, the G and M codes\n"
         "// it accepts, error codes, the tape characters the decoder tells apart, and the board's\n"
         "// serial link; and the block record, block_t, as a macro after the package.\n"
         "// GENERATED by interp_pkg_gen (" << tape_dir << "/interp_pkg_gen.cpp) from\n"
         "// " << tape_dir << "/tape_motions.def, tape_codes.def, tape_errors.def, tape_chars.def and\n"
         "// board_link.def, block_record.def: do not edit.\n"
         "// Regenerate with `cmake --build build --target interp_pkg`; the test\n"
         "// tape.interp_pkg_up_to_date fails while this file differs from what the generator writes.\n"
         "//\n"
         "// Idea: the C++ side (tape library, golden model, reports) expands the same .def files, so\n"
         "// the RTL and the models share one definition of every code (docs/architecture.md,\n"
         "// \"Contracts\"). Refer to the items as interp_pkg::Name: Yosys 0.23 reads no `import`\n"
         "// inside or in the header of a module.\n"
         "//\n"
         "// block_t, the decoded block the block buffer stores, is not declared in the package: its\n"
         "// fields are as wide as interp_top's parameters (IncWidth, SeqWidth, StepWidth), and a\n"
         "// package has no parameters. The one idiom for a parameterised type in a package, a\n"
         "// parameterised class, is rejected by both tools of this flow (Verilator 5.006:\n"
         "// \"Unsupported: Multiple '::'\"; Yosys 0.23: no classes). So the file ends with the macro\n"
         "// `INTERP_BLOCK_T, the packed struct typedef that the modules with those parameters\n"
         "// (tape_decoder, interp_top) expand inside themselves.\n"
         "//\n"
         "// The file is named 0_interp_pkg.sv so that it sorts first: every tool that reads\n"
         "// rtl/*.sv in glob order (verilator --lint-only -Wall rtl/*.sv) meets the package before\n"
         "// the modules that use it.\n"
         "/* verilator lint_off DECLFILENAME */\n"
         "package interp_pkg;\n"
         "/* verilator lint_on DECLFILENAME */\n"
         "\n"
         "  // Constants, not signals: kept out of Verilator's VCD (the modules' own names only).\n"
         "  /* verilator tracing_off */\n"
         "\n"
         "  // Motion codes: the G word's number, stored in a block as it is.\n"
         "  localparam int MotionWidth = "
      << motion_bits
      << ";\n"
         "  typedef enum logic [MotionWidth-1:0] {\n";
  items(out, kMotions, "Motion", motion_bits, false, "");
  out << "  } motion_e;\n"
         "\n"
         "  // G and M codes (a code is <= 99, the word parser's limit: 7 bits hold it).\n";
  std::vector<std::pair<unsigned, std::string>> motions;
  for (const Entry& m : kMotions) motions.emplace_back(m.value, m.comment);
  code_function(out, "g_motion", "A G code that is a motion (tape_motions.def).", motions);
  std::vector<std::pair<unsigned, std::string>> arcs;
  for (const Entry& m : kMotions)
    if (std::string(m.name).rfind("Arc", 0) == 0) arcs.emplace_back(m.value, m.comment);
  code_function(out, "motion_is_arc", "A motion code that is a circular arc; the others are straight.",
                arcs, "motion", motion_bits, "MotionWidth-1");
  code_function(out, "g_setting", "A G code that states what the interpolator always does (tape_codes.def).",
                codes('G', "Setting"));
  code_function(out, "m_end", "An M code that ends the program (tape_codes.def).", codes('M', "End"));
  code_function(out, "m_stop", "An M code that pauses the program after its block (tape_codes.def).",
                codes('M', "Stop"));
  code_function(out, "m_optional_stop", "An M code that pauses it with the optional stop switch on.",
                codes('M', "OptionalStop"));
  code_function(out, "m_tool_on", "An M code that switches the tool on as its block starts.",
                codes('M', "ToolOn"));
  code_function(out, "m_tool_off", "An M code that switches the tool off after its block's motion.",
                codes('M', "ToolOff"));
  out << "\n"
         "  // The feed and rapid overrides (feed_override_i, rapid_override_i): a fraction of\n"
         "  // the block's rate in units of 2^-OverrideFracBits (feed_override.h); OverrideOne is\n"
         "  // 100 %, what a machine without an operator's override ties the inputs to. Only\n"
         "  // the feed generator and the tops read them.\n"
         "  /* verilator lint_off UNUSEDPARAM */\n"
         "  localparam int OverrideWidth = "
      << ncinterp::kOverrideWidth << ";\n"
      << "  localparam int OverrideFracBits = " << ncinterp::kOverrideFracBits << ";\n"
      << "  localparam logic [OverrideWidth-1:0] OverrideOne = " << ncinterp::kOverrideWidth << "'d"
      << ncinterp::kOverrideOne << ";\n"
      << "  localparam int OverrideTens = " << ncinterp::kOverrideTens << ";\n"
      << "  localparam int OverrideTensAtOne = " << ncinterp::kOverrideTensAtOne << ";\n"
      << "  // The boards' operator buttons: sampled every 2^OperatorDebounceWidth clocks\n"
      << "  // (operator_panel.h).\n"
      << "  localparam int OperatorDebounceWidth = " << ncinterp::kOperatorDebounceWidth << ";\n"
      << "  /* verilator lint_on UNUSEDPARAM */\n"
      << "  // The boards' feed override buttons: 10 % a step; tens (0 to OverrideTens) as the\n"
      << "  // override, rounded as the command line rounds a percentage.\n"
      << "  function automatic logic [OverrideWidth-1:0] override_of_tens(input logic [4:0] tens);\n"
      << "    case (tens)\n";
  for (unsigned t = 0; t <= ncinterp::kOverrideTens; ++t)
    out << "      5'd" << t << ": override_of_tens = " << ncinterp::kOverrideWidth << "'d"
        << ncinterp::override_units(10.0 * t) << ";\n";
  out << "      default: override_of_tens = OverrideOne;\n"
      << "    endcase\n"
      << "  endfunction\n";
  out << "\n"
         "  // Error codes: error_code_o (0 while error_o is low).\n"
         "  localparam int ErrCodeWidth = "
      << error_bits
      << ";\n"
         "  typedef enum logic [ErrCodeWidth-1:0] {\n";
  items(out, kErrors, "Err", error_bits, false, "");
  out << "  } tape_error_e;\n"
         "\n"
         "  // Tape characters: a frame's 7 bits without the parity bit (ISO 840 bit 7).\n"
         "  // A package is a library: no one module compares with every character.\n"
         "  /* verilator lint_off UNUSEDPARAM */\n";
  items(out, kChars, "Ch", 7, true, "logic [6:0]");
  out << "\n"
         "  // The board's serial link (board_link.def): its special bytes, the board's own error\n"
         "  // codes (beside the tape errors above), the status lines' kind letters, the digits\n"
         "  // of their block field and of each of their two other fields.\n";
  items(out, kLinkBytes, "Link", 8, true, "logic [7:0]");
  items(out, kLinkCounts, "Link", 32, false, "int");
  items(out, kRealtime, "Realtime", 8, true, "logic [7:0]");
  items(out, kBoardErrors, "BoardErr", 8, true, "logic [7:0]");
  items(out, kStatusKinds, "Status", 8, true, "logic [7:0]");
  out << "  localparam int StatusBlockDigits = " << kStatusBlockDigits << ";\n"
         "  localparam int StatusDigits = " << kStatusDigits << ";\n"
         "  /* verilator lint_on UNUSEDPARAM */\n";
  const size_t commands = std::size(kRealtime);
  out << "  // The realtime commands, one bit each in the list's order: the one a byte is (0: a\n"
         "  // byte that is none). Literals, not the names above: see the code functions.\n"
         "  localparam int RealtimeCommands = " << commands << ";\n"
         "  function automatic logic [RealtimeCommands-1:0] realtime_command(input logic [7:0] b);\n"
         "    case (b)\n";
  for (size_t i = 0; i < commands; ++i)
    out << "      " << literal(8, kRealtime[i].value, true) << ": realtime_command = " << commands << "'b"
        << std::string(commands - 1 - i, '0') << "1" << std::string(i, '0') << ";  // " << kRealtime[i].name
        << "\n";
  out << "      default: realtime_command = '0;\n"
         "    endcase\n"
         "  endfunction\n"
         "\n"
         "endpackage\n";
  block_record_macro(out);
  return out.str();
}

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot read");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Writes the SystemVerilog package interp_pkg from the tape library's .def files"};
  std::string out_path, check_path;
  auto* out_opt = app.add_option("out", out_path, "package file to write (rtl/0_interp_pkg.sv)");
  app.add_option("--check", check_path, "compare this file with the package instead of writing")
      ->excludes(out_opt);
  app.require_option(1);
  CLI11_PARSE(app, argc, argv);
  try {
    const std::string pkg = package(NCINTERP_TAPE_DIR);
    if (!check_path.empty()) {
      if (read_file(check_path) == pkg) return 0;
      std::cerr << check_path << ": out of date with the .def files; regenerate it with "
                << "`cmake --build build --target interp_pkg`\n";
      return 1;
    }
    ncinterp::write_file_atomically(out_path, pkg);
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "interp_pkg_gen: " << e.what() << "\n";
    return 1;
  }
}
