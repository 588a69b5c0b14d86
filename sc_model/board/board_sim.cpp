// The virtual board on a pseudo-terminal (see board_sim.h).
#include "board_sim.h"

#include <fcntl.h>
#include <poll.h>
#include <pty.h>
#include <termios.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>
#include <deque>
#include <filesystem>
#include <memory>
#include <stdexcept>

#include "Vboard_icebreaker.h"
#include "Vboard_icebreaker_trace.h"
#include "Vboard_icestick.h"
#include "Vboard_icestick_trace.h"
#include "boards.h"
#include "atomic_file.h"
#include "operator_panel.h"
#include "operator_pins_model.h"
#include "play_monitor.h"
#include "play_report.h"
#include "status_text.h"
#include "uart_rx_model.h"
#include "uart_tx_model.h"
#include "verilated.h"
#include "verilated_vcd_c.h"

namespace ncinterp::board {
namespace {

// ns -> clocks, rounded up, at least 1 (board_timing.svh's ns_to_cycles).
unsigned ns_to_cycles(double ns, double clock_hz) {
  const double c = std::ceil(ns * clock_hz / 1e9 - 1e-9);
  return c < 1 ? 1u : static_cast<unsigned>(c);
}

// The pty: master (the sim's end) and the slave's path behind a symlink.
class Pty {
 public:
  explicit Pty(const std::string& link) : link_(link) {
    if (openpty(&master_, &slave_, nullptr, nullptr, nullptr) != 0)
      throw std::runtime_error(std::string("openpty: ") + std::strerror(errno));
    termios t{};
    tcgetattr(slave_, &t);
    cfmakeraw(&t);
    tcsetattr(slave_, TCSANOW, &t);
    fcntl(master_, F_SETFL, fcntl(master_, F_GETFL) | O_NONBLOCK);
    const std::string name = ttyname(slave_);
    std::error_code ec;
    if (std::filesystem::is_symlink(link_, ec)) std::filesystem::remove(link_, ec);
    std::filesystem::create_symlink(name, link_, ec);
    if (ec) throw std::runtime_error(link_ + ": cannot create the link to " + name + ": " + ec.message());
  }
  ~Pty() {
    std::error_code ec;
    std::filesystem::remove(link_, ec);
    if (slave_ >= 0) close(slave_);
    close(master_);
  }
  Pty(const Pty&) = delete;
  Pty& operator=(const Pty&) = delete;

  // Once the sender has the slave open, the sim lets go of its own handle so that the
  // sender's close shows as a hang-up on the master.
  void release_slave() {
    if (slave_ >= 0) close(slave_);
    slave_ = -1;
  }
  int master() const { return master_; }

 private:
  std::string link_;
  int master_ = -1, slave_ = -1;
};

// The interpolator's outputs on the board core's obs_<output>_o ports, one per line of
// interp_outputs.def, each as wide as the board's configuration makes it (a position is
// sign-extended from its PosWidth bits).
template <class Model>
InterpOutputs interp_outputs(const Model& m, const InterpConfig& cfg) {
  InterpOutputs o;
#define INTERP_OUTPUT(name, kind, width) \
  o.name = Port##kind::from_signal(static_cast<Port##kind::Signal>(m.obs_##name##_o), width);
#include "interp_outputs.def"
#undef INTERP_OUTPUT
  return o;
}

// The operator at the board's pins (rtl/board/operator_pins.sv). A switch event sets its
// pin's level. A button event presses buttons: a press holds the pin down three debounce
// sample periods and lets it up three more, so that the next press counts. override=P
// presses the feed override's 100 % button, or +10 % or -10 % as often as it takes from
// where the presses before left it; rapid-override=P steps the rapid override's button to
// P. Override presses queue one after another, each button's presses too.
class OperatorHands {
 public:
  // Throws std::invalid_argument for an override the buttons cannot set.
  explicit OperatorHands(const std::vector<OperatorEvent>& events) : events_(events) {
    unsigned tens = kOverrideTensAtOne, rapid = 0;
    for (const OperatorEvent& e : events_) plan_override(e, tens, rapid);  // checks them
  }

  // The pins at `cycle` (the events up to it applied; cycles rise call by call).
  const std::array<bool, kOperatorPins>& at(uint64_t cycle) {
    for (; next_ < events_.size() && events_[next_].cycle <= cycle; ++next_) apply(events_[next_], cycle);
    for (int p = 0; p < kOperatorButtons; ++p) {
      std::deque<uint64_t>& q = presses_[p];
      while (!q.empty() && cycle >= q.front() + kDown) q.pop_front();
      pins_[p] = !q.empty() && cycle >= q.front();
    }
    return pins_;
  }
  // An event or a press still to come.
  bool busy() const {
    if (next_ < events_.size()) return true;
    for (const auto& q : presses_)
      if (!q.empty()) return true;
    return false;
  }
  // A cycle start still to come (an event or a press not yet let up).
  bool start_to_come() const {
    for (size_t i = next_; i < events_.size(); ++i)
      if (events_[i].kind == OperatorEvent::kStart) return true;
    return !presses_[kPinStart].empty();
  }

 private:
  static constexpr uint64_t kDown = 3ull << kOperatorDebounceWidth, kPress = 2 * kDown;

  // An override event's presses: how often which button, from the state (tens, rapid) the
  // presses before left, which it updates. Throws for a value the buttons do not reach.
  static std::pair<int, unsigned> plan_override(const OperatorEvent& e, unsigned& tens, unsigned& rapid) {
    if (e.kind == OperatorEvent::kRapidOverride) {
      const unsigned to = e.value == kOverrideOne ? 0 : e.value == kOverrideOne / 2 ? 1 : 2;
      const unsigned n = (to + 3 - rapid) % 3;
      rapid = to;
      return {kPinRapid, n};
    }
    if (e.kind != OperatorEvent::kFeedOverride) return {-1, 0};
    for (unsigned t = 0; t <= kOverrideTens; ++t) {
      if (override_units(10.0 * t) != e.value) continue;
      const unsigned from = tens;
      tens = t;
      if (t == from) return {kPinFeedReset, 0};
      if (t == kOverrideTensAtOne) return {kPinFeedReset, 1};
      return t > from ? std::pair<int, unsigned>{kPinFeedUp, t - from} : std::pair<int, unsigned>{kPinFeedDown, from - t};
    }
    char percent[32];
    std::snprintf(percent, sizeof percent, "%.3g", e.value * 100.0 / kOverrideOne);
    throw std::invalid_argument(std::string("--events: the board's feed override buttons step by 10 % (0, 10, ..., "
                                            "200 %): an override of ") + percent + " % is none of their steps");
  }

  void press(int pin, unsigned times, uint64_t cycle, uint64_t& free_at) {
    uint64_t t = std::max(cycle, free_at);
    for (unsigned i = 0; i < times; ++i, t += kPress) presses_[pin].push_back(t);
    free_at = t;
  }

  void apply(const OperatorEvent& e, uint64_t cycle) {
    switch (e.kind) {
      case OperatorEvent::kHold: return press(kPinHold, 1, cycle, free_at_[kPinHold]);
      case OperatorEvent::kStart: return press(kPinStart, 1, cycle, free_at_[kPinStart]);
      case OperatorEvent::kEStop: pins_[kPinEStop] = true; return;
      case OperatorEvent::kLimitX: pins_[kPinLimitX] = true; return;
      case OperatorEvent::kLimitY: pins_[kPinLimitY] = true; return;
      case OperatorEvent::kOptionalStop: pins_[kPinOptionalStop] = e.value != 0; return;
      case OperatorEvent::kFeedOverride:
      case OperatorEvent::kRapidOverride: {
        const auto [pin, times] = plan_override(e, tens_, rapid_);
        return press(pin, times, cycle, override_free_at_);
      }
    }
  }

  std::vector<OperatorEvent> events_;
  size_t next_ = 0;
  std::array<bool, kOperatorPins> pins_{};
  std::array<std::deque<uint64_t>, kOperatorButtons> presses_;  // press starts, per button
  uint64_t free_at_[kOperatorButtons] = {}, override_free_at_ = 0;
  unsigned tens_ = kOverrideTensAtOne, rapid_ = 0;  // the overrides as the presses leave them
};

template <class Model>
class Runner {
 public:
  // With a VCD: the model is traced into `vcd`, which opens `vcd_path`.
  Runner(const BoardSimOptions& o, const CoreConfig& c, const InterpConfig& cfg, Pty& pty,
         VerilatedVcdC* vcd, const std::string& vcd_path)
      : o_(o), c_(c), cfg_(cfg), pty_(pty), context_(std::make_unique<VerilatedContext>()), vcd_(vcd) {
    if (vcd_) context_->traceEverOn(true);
    m_ = std::make_unique<Model>(context_.get(), "board");
    if (vcd_) {
      trace(*m_);
      vcd_->open(vcd_path.c_str());
    }
    Model& m = *m_;
    m.bit_cycles_i = c.bit_cycles;
    m.feed_modulus_i = c.feed_modulus;
    m.rapid_step_i = cfg.rapid_step;
    m.accel_step_i = cfg.accel_step;
    m.setup_cycles_i = c.setup_cycles;
    m.pulse_cycles_i = c.pulse_cycles;
    m.low_cycles_i = c.low_cycles;
    m.rx_i = 1;
    m.rst_ni = 0;
    edge();
    m.rst_ni = 1;
  }

  BoardSimResult run() {
    BoardSimResult r;
    r.bit_cycles = c_.bit_cycles;
    r.realtime.assign(kRealtimeCommandCount, 0);
    Model& m = *m_;
    UartTxModel host_tx;
    UartRxModel host_rx;
    std::deque<uint8_t> in, out;
    std::string line;
    bool stopped_by_xoff = false, sender_seen = false, final_line = false;
    InterpOutputs last = interp_outputs(m, cfg_);
    trace_.push_back({0, last});
    auto idle_since = std::chrono::steady_clock::now();
    const uint64_t byte_cycles = 10ull * c_.bit_cycles;
    uint64_t final_deadline = 0;

    OperatorHands hands(o_.events);

    while (!final_line) {
      // The operator's pins at this clock.
      const std::array<bool, kOperatorPins>& pins = hands.at(cycle_);
      m.hold_i = pins[kPinHold];
      m.start_i = pins[kPinStart];
      m.feed_up_i = pins[kPinFeedUp];
      m.feed_down_i = pins[kPinFeedDown];
      m.feed_reset_i = pins[kPinFeedReset];
      m.rapid_cycle_i = pins[kPinRapid];
      m.estop_i = pins[kPinEStop];
      m.limit_x_i = pins[kPinLimitX];
      m.limit_y_i = pins[kPinLimitY];
      m.optional_stop_i = pins[kPinOptionalStop];
      if (last.paused && !hands.start_to_come()) {
        r.paused = true;  // no cycle start to come: the program waits for good
        break;
      }

      // The sender's bytes: read when the wire has none waiting (at most once a byte time).
      if (in.empty() && cycle_ % byte_cycles == 0) {
        const bool board_idle = !last.busy && m.obs_fifo_level_o == 0 && host_tx.ready();
        uint8_t buf[256];
        // Nothing to simulate while nothing has been sent yet: wait for the sender.
        pollfd p{pty_.master(), POLLIN, 0};
        poll(&p, 1, sender_seen ? 0 : 100);
        const ssize_t n = read(pty_.master(), buf, sizeof buf);
        if (n > 0) {
          in.insert(in.end(), buf, buf + n);
          if (!sender_seen) pty_.release_slave();
          sender_seen = true;
          idle_since = std::chrono::steady_clock::now();
        } else if (sender_seen && hands.busy()) {
          // An operator's event is still to come: the board waits for it, not for the
          // sender; simulate on at full speed.
        } else if (board_idle || !sender_seen) {
          const double idle = std::chrono::duration<double>(std::chrono::steady_clock::now() - idle_since).count();
          if (idle > o_.idle_timeout_s) {
            r.timed_out = true;
            break;
          }
          if (sender_seen && board_idle) usleep(1000);  // the sender is slow: do not spin
        }
      }
      flush(out);

      // One clock: host-side UART and board sample the values before the edge.
      const bool board_tx = m.tx_o, cts_n = m.cts_no;
      const bool allowed = o_.flow == Flow::kRtsCts ? !cts_n : o_.flow == Flow::kXonXoff ? !stopped_by_xoff : true;
      const bool offer = host_tx.ready() && !in.empty() && allowed;
      if (host_tx.ready() && !in.empty() && !allowed) ++r.flow_hold_cycles;
      m.rx_i = host_tx.tx();
      edge();
      host_tx.tick(offer ? in.front() : 0, offer, c_.bit_cycles);
      if (offer) in.pop_front();
      host_rx.tick(board_tx, c_.bit_cycles);
      if (host_rx.valid()) {
        const uint8_t b = host_rx.data();
        out.push_back(b);
        if (b == kLinkXoff) {
          stopped_by_xoff = true;
          ++r.xoff_sent;
        } else if (b == kLinkXon) {
          stopped_by_xoff = false;
        } else if (b == kLinkAck) {
          ++r.acks_sent;
        } else if (b == '\n') {
          if (!line.empty() && line.back() == '\r') line.pop_back();
          r.status_lines.push_back(line);
          if (!line.empty() && (line[0] == 'D' || line[0] == 'E')) final_line = true;
          line.clear();
        } else {
          line += static_cast<char>(b);
        }
      }
      // The frames the board received (not its realtime bytes; the EOT frame is not one),
      // and the realtime commands it took.
      if (m.obs_rx_valid_o && m.obs_rx_data_o != kLinkEndOfTape) r.frames.push_back(m.obs_rx_data_o);
      for (int i = 0; i < kRealtimeCommandCount; ++i) r.realtime[i] += m.obs_realtime_o >> i & 1;
      r.max_fifo_level = std::max<unsigned>(r.max_fifo_level, m.obs_fifo_level_o);
      r.board_error = m.board_error_code_o;

      const InterpOutputs now = interp_outputs(m, cfg_);
      if (!(now == last)) {
        trace_.push_back({cycle_, now});
        last = now;
      }
      if ((last.done || last.error || r.board_error) && final_deadline == 0)
        final_deadline = cycle_ + 200 * byte_cycles;  // a few status lines
      if (final_deadline && cycle_ > final_deadline) break;  // no final line: reported below
      if (o_.max_cycles && cycle_ >= o_.max_cycles) break;
    }
    // The last status bytes, then wait (bounded) for the sender to read them and close;
    // only after a final line (no sender waits for more after it; after a pause or at the
    // cycle limit one would, and closing the pty tells it the board is gone).
    const auto t0 = std::chrono::steady_clock::now();
    while (final_line && std::chrono::steady_clock::now() - t0 < std::chrono::seconds(5)) {
      flush(out);
      if (!out.empty()) {
        usleep(1000);
        continue;
      }
      uint8_t buf[256];
      pollfd p{pty_.master(), POLLIN, 0};
      if (poll(&p, 1, 50) > 0) {
        const ssize_t n = read(pty_.master(), buf, sizeof buf);
        if (n < 0 && errno == EIO) break;  // the sender closed the port
        if (n == 0) break;
      }
      if (!sender_seen) break;
    }
    r.play.summary.cycles = cycle_;
    final_cycle_ = cycle_;
    return r;
  }

  // Replays the recorded outputs into the play monitor, clock by clock.
  system::PlaySummary replay(const tape::Program& program) const {
    system::PlayMonitor monitor(program, cfg_);
    size_t next = 0;
    InterpOutputs cur;
    for (uint64_t c = 0; c <= final_cycle_; ++c) {
      while (next < trace_.size() && trace_[next].first == c) cur = trace_[next++].second;
      monitor.observe(c, cur);
      if (monitor.finished()) break;
    }
    return monitor.finish(cur);
  }

  uint64_t cycles() const { return final_cycle_; }

 private:
  void trace(Model& m) { m.trace(vcd_, 99); }

  void edge() {
    Model& m = *m_;
    m.clk_i = 0;
    m.eval();
    if (vcd_) vcd_->dump(2 * cycle_);
    m.clk_i = 1;
    m.eval();
    ++cycle_;
    if (vcd_) vcd_->dump(2 * cycle_ - 1);
  }

  void flush(std::deque<uint8_t>& out) {
    while (!out.empty()) {
      uint8_t buf[256];
      size_t n = 0;
      while (n < sizeof buf && n < out.size()) buf[n] = out[n], ++n;
      const ssize_t w = write(pty_.master(), buf, n);
      if (w <= 0) return;  // the sender is not reading yet: keep them
      out.erase(out.begin(), out.begin() + w);
    }
  }

  const BoardSimOptions& o_;
  CoreConfig c_;
  InterpConfig cfg_;  // the interpolator as the board builds it
  Pty& pty_;
  std::unique_ptr<VerilatedContext> context_;
  VerilatedVcdC* vcd_;
  std::unique_ptr<Model> m_;
  uint64_t cycle_ = 0, final_cycle_ = 0;
  std::vector<std::pair<uint64_t, InterpOutputs>> trace_;
};

// The fast models have no trace(); only the traced ones are given a VCD.
template <>
void Runner<Vboard_icestick>::trace(Vboard_icestick&) {}
template <>
void Runner<Vboard_icebreaker>::trace(Vboard_icebreaker&) {}

template <class Model>
BoardSimResult run_with(const BoardSimOptions& o, const CoreConfig& c, const InterpConfig& cfg, Pty& pty,
                        VerilatedVcdC* vcd, const std::string& vcd_path) {
  Runner<Model> runner(o, c, cfg, pty, vcd, vcd_path);
  const auto t0 = std::chrono::steady_clock::now();
  BoardSimResult r = runner.run();
  r.readback = tape::parse_frames_partial(r.frames, tape_format_of(cfg));
  system::PlayResult& p = r.play;
  p.summary = runner.replay(r.readback.program);
  p.summary.paused = r.paused;
  p.summary.cycles = std::max(p.summary.cycles, runner.cycles());
  p.config = cfg;
  p.clock_hz = o.clock_hz;
  p.accel_mm_s2 = o.accel_mm_s2 < 0 ? board_named(o.board).accel_mm_s2 : o.accel_mm_s2;
  p.reader_cps = o.baud / 10.0;
  p.cycles_per_frame = 10ull * c.bit_cycles;
  p.frames = r.frames.size();
  p.blocks_on_tape = r.readback.program.blocks.size();
  p.frames_taken = r.frames.size();
  p.max_cycles = o.max_cycles;
  p.limit_reached = o.max_cycles && runner.cycles() >= o.max_cycles;
  p.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

}  // namespace

Flow flow_named(const std::string& name) {
  for (Flow f : {Flow::kRtsCts, Flow::kXonXoff, Flow::kCount})
    if (name == flow_name(f)) return f;
  throw std::invalid_argument("unknown flow control '" + name + "' (rtscts, xonxoff, count)");
}

const char* flow_name(Flow f) {
  return f == Flow::kRtsCts ? "rtscts" : f == Flow::kXonXoff ? "xonxoff" : "count";
}

CoreConfig core_config(const BoardSimOptions& o) {
  if (!(o.clock_hz >= 1e5 && o.clock_hz <= 1e9)) throw std::runtime_error("--clock-hz must be between 1e5 and 1e9");
  if (o.baud == 0) throw std::runtime_error("--baud must be positive");
  CoreConfig c;
  const double bit = std::round(o.clock_hz / o.baud);
  if (bit < 4 || bit > 4095)
    throw std::runtime_error("--baud: " + std::to_string(bit) + " clocks per bit at this clock; the board needs 4 to 4095");
  c.bit_cycles = static_cast<uint16_t>(bit);
  c.feed_modulus = InterpConfig::feed_modulus_for(o.clock_hz, 3);
  const unsigned pulse = ns_to_cycles(o.pulse_ns, o.clock_hz);
  const unsigned setup = ns_to_cycles(o.dir_setup_ns, o.clock_hz);
  const unsigned hold = ns_to_cycles(o.dir_hold_ns, o.clock_hz);
  const unsigned hold_low = hold > pulse ? hold - pulse : 1;
  const unsigned low = std::max(ns_to_cycles(o.low_ns, o.clock_hz), hold_low);
  if (pulse > 255 || setup > 255 || low > 255)
    throw std::runtime_error("step timing: more than 255 clocks (board_core's 8-bit counters)");
  c.pulse_cycles = static_cast<uint8_t>(pulse);
  c.setup_cycles = static_cast<uint8_t>(setup);
  c.low_cycles = static_cast<uint8_t>(low);
  return c;
}

BoardSimResult run_board_sim(const BoardSimOptions& o,
                             const std::function<void(const std::string&)>& on_ready) {
  // The board core of the board's configuration (sc_model/board/CMakeLists.txt).
  const bool circle_mode = board_named(o.board).circle_mode;
  const CoreConfig c = core_config(o);
  const InterpConfig cfg = board_interp_config(board_named(o.board), o.clock_hz, o.accel_mm_s2, o.rapid_mm_min);
  if (!o.events.empty() && !board_named(o.board).operator_pins)
    throw std::invalid_argument("--events: the " + o.board + "'s core is built without the operator's pins (docs/board.md)");
  OperatorHands check(o.events);  // an override the buttons cannot set is refused here
  std::unique_ptr<AtomicOutputFile> vcd_file;
  std::unique_ptr<VerilatedVcdC> vcd;
  if (!o.vcd_path.empty()) vcd_file = std::make_unique<AtomicOutputFile>(o.vcd_path);
  Pty pty(o.pty_link);
  if (on_ready) on_ready(o.pty_link);
  if (vcd_file) vcd = std::make_unique<VerilatedVcdC>();
  BoardSimResult r =
      vcd_file ? (circle_mode ? run_with<Vboard_icebreaker_trace>(o, c, cfg, pty, vcd.get(), vcd_file->temp_path())
                              : run_with<Vboard_icestick_trace>(o, c, cfg, pty, vcd.get(), vcd_file->temp_path()))
               : (circle_mode ? run_with<Vboard_icebreaker>(o, c, cfg, pty, nullptr, "")
                              : run_with<Vboard_icestick>(o, c, cfg, pty, nullptr, ""));
  if (vcd) {
    vcd->close();
    if (r.play.ok()) vcd_file->commit();
  }
  return r;
}

nlohmann::json board_sim_report(const BoardSimResult& r, const BoardSimOptions& o) {
  nlohmann::json j = system::play_report(r.play, o.pty_link, "board:" + o.board, r.readback.error);
  j["board"] = {{"name", o.board},
                {"baud", o.baud},
                {"bit_cycles", r.bit_cycles},
                {"flow", flow_name(o.flow)},
                {"frames_received", r.frames.size()},
                {"max_fifo_level", r.max_fifo_level},
                {"flow_hold_cycles", r.flow_hold_cycles},
                {"xoff_sent", r.xoff_sent},
                {"acks_sent", r.acks_sent},
                {"board_error", r.board_error},
                {"status_lines", r.status_lines},
                {"timed_out", r.timed_out}};
  nlohmann::json realtime = nlohmann::json::object();
  for (int i = 0; i < kRealtimeCommandCount; ++i) realtime[kRealtimeCommands[i].name] = r.realtime[i];
  j["board"]["realtime_commands"] = realtime;
  if (r.board_error) {
    j["status"] = "error";
    j["error"] = {{"code", r.board_error}, {"message", board_error_message(r.board_error)}};
  }
  if (r.timed_out) j["status"] = "error";
  return j;
}

}  // namespace ncinterp::board
