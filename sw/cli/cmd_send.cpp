// `ncinterp send TAPE --port DEV [--baud B] [--flow rtscts|xonxoff|count] [--keys]`: punches
// a tape into a board over a serial port (docs/board.md): the tape's frames, then the EOT
// frame that ends the tape, with flow control; prints the board's status lines in words
// (each block once) and exits with the board's verdict. With character counting, keys typed
// (or piped in with --keys) send the operator's realtime commands: hold, cycle start, the
// overrides, E-stop (board_link.def's list).
// Idea: termios only. The port is raw 8N1 at the baud rate. CRTSCTS (the USB-serial chip
// stops before a byte while the board holds CTS# high) or IXON (the chip stops on the
// board's XOFF until XON) does the flow control, so a plain write loop never overruns the
// board; or, with `count`, the chip holds nothing back and send keeps at most the board's
// FIFO of tape bytes unacknowledged (the board ACKs every LinkAckBytes bytes it takes), so
// a realtime command, written ahead of any tape byte not yet written, reaches the board
// even while a held machine's FIFO is full. XON/XOFF and ACK bytes are dropped from what
// the board sends; every other line is a status line (rtl/board/status_line.sv). Progress
// and the commands sent go to stderr, only on a terminal. Exit (README, "Exit codes"): 0
// when the board reports the program done; 5 when it reports an E-stop or a limit switch;
// 1 with "TAPE: block N, offset K: message" when it reports a tape error (the software
// reader's wording when it finds the same error), or on unusable options; 4 when the port
// closes, or nothing moves (no byte read, none written: the board silent, or holding the
// flow control) for longer than --timeout.
#include <fcntl.h>
#include <poll.h>
#include <termios.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <deque>
#include <iostream>
#include <map>
#include <optional>
#include <stdexcept>

#include "board_sim.h"
#include "command_registry.h"
#include "feed_override.h"
#include "machine_options.h"
#include "play_run.h"
#include "status_text.h"
#include "tape.h"

namespace ncinterp::cli {
namespace {

struct SendArgs {
  std::string tape, port, flow = "rtscts";
  unsigned baud = 115200;
  double timeout_s = 600;
  std::optional<bool> keys;  // read keys from stdin (default: when it is a terminal, with count)
};

speed_t speed_for(unsigned baud) {
  static const std::map<unsigned, speed_t> speeds = {
      {9600, B9600},     {19200, B19200},     {38400, B38400},     {57600, B57600},
      {115200, B115200}, {230400, B230400},   {460800, B460800},   {500000, B500000},
      {921600, B921600}, {1000000, B1000000}, {2000000, B2000000}, {3000000, B3000000}};
  const auto it = speeds.find(baud);
  if (it == speeds.end()) throw std::runtime_error("--baud " + std::to_string(baud) + " is not a standard termios rate");
  return it->second;
}

// The port, raw 8N1 with the flow control asked for; closed on destruction.
class Port {
 public:
  Port(const std::string& path, speed_t speed, board::Flow flow) {
    fd_ = open(path.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK);
    if (fd_ < 0) throw std::runtime_error(path + ": " + std::strerror(errno));
    termios t{};
    if (tcgetattr(fd_, &t) != 0) {
      close(fd_);
      throw std::runtime_error(path + ": not a serial port (" + std::string(std::strerror(errno)) + ")");
    }
    cfmakeraw(&t);
    cfsetispeed(&t, speed);
    cfsetospeed(&t, speed);
    t.c_cflag |= CLOCAL | CREAD;
    t.c_cflag &= ~static_cast<tcflag_t>(CSTOPB | PARENB);
    if (flow == board::Flow::kRtsCts) t.c_cflag |= CRTSCTS;
    if (flow == board::Flow::kXonXoff) t.c_iflag |= IXON;
    if (tcsetattr(fd_, TCSANOW, &t) != 0) {
      close(fd_);
      throw std::runtime_error(path + ": cannot set the line (" + std::string(std::strerror(errno)) + ")");
    }
    tcflush(fd_, TCIOFLUSH);
  }
  ~Port() { close(fd_); }
  Port(const Port&) = delete;
  Port& operator=(const Port&) = delete;
  int fd() const { return fd_; }

 private:
  int fd_ = -1;
};

// The operator's keys on standard input. A terminal is read key by key without echo while
// send runs, and put back as it was at the end, on Ctrl-C and on SIGTERM.
termios g_saved_terminal;
void restore_terminal_and_die(int sig) {
  tcsetattr(STDIN_FILENO, TCSANOW, &g_saved_terminal);
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

class Keys {
 public:
  explicit Keys(bool on) : open_(on) {
    if (!on || !isatty(STDIN_FILENO) || tcgetattr(STDIN_FILENO, &g_saved_terminal) != 0) return;
    termios t = g_saved_terminal;
    t.c_lflag &= ~static_cast<tcflag_t>(ICANON | ECHO);
    t.c_cc[VMIN] = 1;
    t.c_cc[VTIME] = 0;
    std::signal(SIGINT, restore_terminal_and_die);
    std::signal(SIGTERM, restore_terminal_and_die);
    terminal_ = tcsetattr(STDIN_FILENO, TCSANOW, &t) == 0;
  }
  ~Keys() {
    if (terminal_) tcsetattr(STDIN_FILENO, TCSANOW, &g_saved_terminal);
  }
  Keys(const Keys&) = delete;
  Keys& operator=(const Keys&) = delete;
  bool open() const { return open_; }
  // The keys typed since the last call; an empty string and open() false at the input's end.
  std::string read_keys() {
    char buf[64];
    const ssize_t n = read(STDIN_FILENO, buf, sizeof buf);
    if (n <= 0) {
      if (n == 0 || (errno != EAGAIN && errno != EINTR)) open_ = false;
      return "";
    }
    return std::string(buf, static_cast<size_t>(n));
  }

 private:
  bool open_ = false, terminal_ = false;
};

// What send has asked of the board: it shows this, as the board reports no overrides (the
// board's own buttons change them too, unseen here).
struct OperatorAsked {
  bool held = false, stopped = false;
  unsigned tens = kOverrideTensAtOne, rapid_step = 0;

  void apply(const std::string& command) {
    if (command == "Hold") held = true;
    else if (command == "Start") held = false;
    else if (command == "FeedUp") tens = std::min(tens + 1, kOverrideTens);
    else if (command == "FeedDown") tens = tens == 0 ? 0 : tens - 1;
    else if (command == "FeedReset") tens = kOverrideTensAtOne;
    else if (command == "RapidCycle") rapid_step = (rapid_step + 1) % 3;
    else if (command == "EStop") stopped = true;
  }
  std::string text() const {
    return std::string(stopped ? "E-stop" : held ? "hold" : "run") + ", feed " + std::to_string(10 * tens) +
           " %, rapid " + std::to_string(100 >> rapid_step) + " %";
  }
};

int run(const SendArgs& a) {
  const speed_t speed = speed_for(a.baud);
  std::vector<uint8_t> frames = tape::load_frames(a.tape);
  const size_t tape_frames = frames.size();
  frames.push_back(board::kLinkEndOfTape);
  const unsigned frac_digits = interp_config(12e6).frac_digits;
  // The software reader's view of the tape: the blocks the board plays (to resolve the
  // status lines' N) and the first error, if any.
  const tape::ParseResult readback = tape::parse_frames_partial(
      std::vector<uint8_t>(frames.begin(), frames.begin() + static_cast<long>(tape_frames)),
      tape_format_of(interp_config(12e6)));
  board::StatusTracker tracker(readback.program);
  const board::Flow flow = board::flow_named(a.flow);
  const bool counting = flow == board::Flow::kCount;
  if (a.keys.value_or(false) && !counting)
    throw std::invalid_argument("--keys: realtime commands need --flow count (a board that ACKs what it takes)");
  Port port(a.port, speed, flow);
  const bool tty = isatty(STDERR_FILENO);
  Keys keys(a.keys.value_or(counting && isatty(STDIN_FILENO)));
  if (keys.open() && tty) {
    std::string help = "send: keys:";
    for (const board::RealtimeCommand& c : board::kRealtimeCommands)
      help += std::string(" ") + c.key + " " + c.name;
    std::fprintf(stderr, "%s\n", help.c_str());
  }

  size_t sent = 0;
  uint64_t acks = 0;           // ACKs read (count)
  std::deque<uint8_t> urgent;  // realtime bytes not yet written: before any tape byte
  OperatorAsked asked;
  // With count: how many more tape bytes may go out (at most the FIFO unacknowledged).
  const auto window = [&]() -> size_t {
    if (!counting) return frames.size();
    const uint64_t unacked = sent - std::min<uint64_t>(sent, acks * board::kLinkAckBytes);
    return unacked >= board::kLinkFifoBytes ? 0 : board::kLinkFifoBytes - unacked;
  };
  std::string line;
  std::string last_block = "-";
  std::optional<uint32_t> shown_block;  // the block of the last line shown
  auto last_moved = std::chrono::steady_clock::now();  // a byte read or written
  auto last_progress = last_moved - std::chrono::seconds(1);
  bool progress_shown = false;
  const auto clear_progress = [&] {
    if (progress_shown) std::fprintf(stderr, "\r%70s\r", "");
    progress_shown = false;
  };
  for (;;) {
    const bool to_write = !urgent.empty() || (sent < frames.size() && window() > 0);
    pollfd fds[2] = {{port.fd(), static_cast<short>(POLLIN | (to_write ? POLLOUT : 0)), 0},
                     {STDIN_FILENO, POLLIN, 0}};
    if (poll(fds, keys.open() ? 2 : 1, 200) < 0 && errno != EINTR)
      throw std::runtime_error(a.port + ": " + std::strerror(errno));
    const pollfd& p = fds[0];
    if (keys.open() && (fds[1].revents & (POLLIN | POLLHUP))) {
      // A command's byte twice, back to back: the board takes a pair as one command.
      for (const char k : keys.read_keys()) {
        for (const board::RealtimeCommand& c : board::kRealtimeCommands) {
          if (c.key != k) continue;
          urgent.insert(urgent.end(), {c.byte, c.byte});
          asked.apply(c.name);
          if (tty) {
            clear_progress();
            std::fprintf(stderr, "send: %s (%s)\n", c.name, asked.text().c_str());
          }
        }
      }
    }
    if ((p.revents & POLLOUT) && to_write) {
      uint8_t buf[64];
      size_t n = 0;
      for (; n < urgent.size() && n < sizeof buf; ++n) buf[n] = urgent[n];
      const bool tape = n == 0;
      if (tape) {
        n = std::min({sizeof buf, frames.size() - sent, window()});
        std::copy_n(frames.begin() + static_cast<long>(sent), n, buf);
      }
      const ssize_t w = write(port.fd(), buf, n);
      if (w > 0) {
        if (tape) sent += static_cast<size_t>(w);
        else urgent.erase(urgent.begin(), urgent.begin() + w);
        last_moved = std::chrono::steady_clock::now();
      } else if (w < 0 && errno != EAGAIN && errno != EINTR) {
        throw std::runtime_error(a.port + ": write: " + std::strerror(errno));
      }
    }
    if (p.revents & (POLLIN | POLLHUP | POLLERR)) {
      uint8_t buf[256];
      const ssize_t n = read(port.fd(), buf, sizeof buf);
      if (n == 0 || (n < 0 && errno != EAGAIN && errno != EINTR)) {
        clear_progress();
        std::cerr << a.tape << ": " << a.port << " closed before the board reported the end of the program\n";
        return 4;
      }
      if (n > 0) last_moved = std::chrono::steady_clock::now();
      for (ssize_t i = 0; i < n; ++i) {
        const uint8_t b = buf[i];
        if (b == board::kLinkAck) ++acks;
        if (b == board::kLinkXon || b == board::kLinkXoff || b == board::kLinkAck || b == '\r') continue;
        if (b != '\n') {
          line += static_cast<char>(b);
          continue;
        }
        clear_progress();
        const std::optional<board::StatusLine> raw = board::parse_status_line(line);
        if (!raw) {
          std::printf("board: %s\n", line.c_str());
        } else if (raw->kind == board::kStatusError) {
          std::fflush(stdout);
          board::BoardStatus s = tracker.resolve(*raw, std::min(sent, tape_frames));
          // The software reader's words and place for the same error, if it finds it (the
          // board sends the low bits of N and the offset).
          const tape::TapeErrorInfo* e = readback.error ? &*readback.error : nullptr;
          const bool same = e && e->code == raw->code &&
                            e->block % (1u << (4 * board::kStatusBlockDigits)) == raw->block &&
                            e->offset % (1u << (4 * board::kStatusDigits)) == raw->offset;
          if (same) {
            s.block = e->block;
            s.offset = e->offset;
          }
          // A stop (E-stop, limit switch) is the operator's or the machine's, not the tape's.
          if (is_stop_error(raw->code)) {
            std::cerr << a.tape << ": stopped in block N" << s.block << ": " << board::board_error_message(raw->code)
                      << "\n";
            return kExitStopped;
          }
          std::cerr << a.tape << ": block N" << s.block << ", offset " << s.offset << ": "
                    << (same ? e->message : board::board_error_message(raw->code)) << "\n";
          return 1;
        } else {
          const board::BoardStatus s = tracker.resolve(*raw, std::min(sent, tape_frames));
          // A line every line time while the machine moves: each block is shown once, at
          // its first line, and the end.
          if (s.kind == board::kStatusDone || shown_block != s.block) {
            std::printf("%s\n", board::describe(s, frac_digits).c_str());
            std::fflush(stdout);
          }
          shown_block = s.block;
          last_block = "N" + std::to_string(s.block);
          if (s.kind == board::kStatusDone) {
            std::printf("%s: %zu frames sent\n", a.tape.c_str(), tape_frames);
            return 0;
          }
        }
        line.clear();
      }
    }
    const auto now = std::chrono::steady_clock::now();
    if (asked.held) last_moved = now;  // a machine on hold is silent for as long as it holds
    if (now - last_moved > std::chrono::duration<double>(a.timeout_s)) {
      clear_progress();
      std::cerr << a.tape << ": nothing moved for " << a.timeout_s << " s: the board "
                << (sent == frames.size() ? "said nothing" : "held the flow control") << " after "
                << std::min(sent, tape_frames) << " of " << tape_frames << " frames (last block "
                << last_block << ")\n";
      return 4;
    }
    if (tty && now - last_progress > std::chrono::milliseconds(200)) {
      last_progress = now;
      std::fprintf(stderr, "\rsend: %zu of %zu frames, block %s%s   ", std::min(sent, tape_frames), tape_frames,
                   last_block.c_str(), keys.open() ? (", " + asked.text()).c_str() : "");
      progress_shown = true;
    }
  }
}

void setup(CLI::App& app) {
  auto args = std::make_shared<SendArgs>();
  CLI::App* cmd = app.add_subcommand("send", "Send a tape to a board over a serial port");
  cmd->add_option("tape", args->tape, "Tape: .tape (frames with parity) or plain text (.nc)")->required();
  cmd->add_option("--port", args->port, "Serial port (/dev/ttyUSB1, or board-sim's --pty link)")->required();
  cmd->add_option("--baud", args->baud, "Baud rate (the board's)")->capture_default_str();
  cmd->add_option("--flow", args->flow,
                  "Flow control: rtscts (iCEstick), count (iCEBreaker: counts the board's ACKs, and "
                  "lets realtime commands through) or xonxoff")
      ->check(CLI::IsMember({"rtscts", "xonxoff", "count"}))
      ->capture_default_str();
  cmd->add_flag("--keys,!--no-keys", args->keys,
                "Send the operator's realtime commands for keys read from standard input (h hold, s "
                "cycle start, + - = feed override, g rapid override, x E-stop; docs/board.md); default: "
                "on when standard input is a terminal and --flow is count");
  cmd->add_option("--timeout", args->timeout_s,
                  "Give up when nothing moves this long (no byte from the board, none sent), s")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cmd->callback([args] { run_command("send", [&] { return run(*args); }); });
}

const CommandRegistration registration("send", setup);

}  // namespace
}  // namespace ncinterp::cli
