// The SystemC system: tape reader, one interpolator engine, and the monitor that watches
// the engine's outputs every clock, controls the VCD window and stops the run.
// Idea: one SystemC process (a thread) clocks the whole system as plain C++: per clock the
// reader (FrameSource, the cosim's own) and the engine (engine.h) take one edge and the
// monitor sees the outputs. SystemC time is not advanced clock by clock outside a VCD
// window: it catches up when a window opens and at the end, so the scheduler costs nothing
// per clock.
// Inside a window the thread runs clock by clock, half a period at a time, and drives the
// wave signals (interp_signals.h) that the golden engine's SystemC tracer records.
// Clock and reset: the first rising edge (t = one period) is the reset edge, cycle 0;
// rst_ni is released at the following falling edge; cycle c is the c-th rising edge after
// it, at (c + 1) periods. The monitor samples at falling edges, when every output of edge
// c is settled, and the reader and the engine see at edge c + 1 what was there before it.
#pragma once
#include <functional>
#include <memory>
#include <string>

#include <systemc>

#include "engine.h"
#include "frame_source.h"
#include "interp_signals.h"
#include "play_monitor.h"
#include "vcd_window.h"

namespace ncinterp::system {

struct SystemSetup {
  InterpConfig config;
  EngineKind engine = EngineKind::kGolden;
  double clock_hz = 1e6;
  std::string vcd_path;  // empty: no VCD
  CycleWindow vcd_window;
  uint64_t max_cycles = 0;
  uint64_t progress_every = 1 << 16;  // cycles between progress calls
  // Tick every clock; otherwise the clocks where the golden engine changes nothing but its
  // feed phase and the reader waits are passed in one step outside a VCD window (the
  // monitor sees the same outputs: PlayMonitor::observe_quiet).
  bool every_clock = false;
  std::function<void(uint64_t cycle, size_t blocks_done)> progress;
};

class SystemTop : public sc_core::sc_module {
 public:
  SystemTop(sc_core::sc_module_name name, const SystemSetup& setup, FrameSource source,
            const tape::Program& program);
  ~SystemTop() override;

  // Call after the simulation stopped: closes the VCD if it is still open.
  void finish();

  PlayMonitor& monitor() { return monitor_; }
  // The engine's outputs after the last edge taken (the ones the monitor saw last).
  const InterpOutputs& outputs() const { return engine_->outputs(); }
  const FrameSource& source() const { return source_; }
  bool limit_reached() const { return limit_reached_; }
  bool vcd_started() const { return vcd_open_ || vcd_closed_; }
  uint64_t cycle() const { return cycle_; }

 private:
  void run();
  // The work at the falling edge after edge cycle_; false when the run is over.
  bool falling_edge();
  // The quiet clocks after edge cycle_ that can be passed in one step (0: tick the next).
  uint64_t quiet_clocks() const;
  // Brings SystemC time to the falling edge after edge cycle_ (outside a VCD window it
  // lags behind the clocks).
  void catch_up();
  void open_vcd();
  // The wave signals of this half clock (clk high: edge cycle_; low: the fall after it).
  void drive_waves(bool clk);

  SystemSetup setup_;
  uint64_t period_ps_;
  WaveSignals waves_;
  FrameSource source_;
  std::unique_ptr<Engine> engine_;
  PlayMonitor monitor_;
  uint64_t cycle_ = 0;
  bool reset_taken_ = false;  // the engine has taken the reset edge
  bool in_reset_ = true;      // rst_ni low: until the fall after the reset edge
  bool vcd_open_ = false, vcd_closed_ = false;
  bool limit_reached_ = false;
};

}  // namespace ncinterp::system
