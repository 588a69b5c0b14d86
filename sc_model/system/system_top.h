// The SystemC system: clock, tape reader, one interpolator engine, and the monitor that
// watches the engine's ports every clock, controls the VCD window and stops the run.
// Idea: the top module is named "SystemC" (see engine.h: that makes the two tracers' signal
// names equal). Clock and reset: the first rising edge (t = one period) is the reset edge,
// cycle 0; rst_ni is released at the following falling edge; cycle c is the c-th rising edge
// after it. The monitor samples at falling edges, when every output of edge c is settled.
#pragma once
#include <functional>
#include <memory>
#include <string>

#include <systemc>

#include "engine.h"
#include "interp_signals.h"
#include "play_monitor.h"
#include "tape_reader_module.h"
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
  std::function<void(uint64_t cycle, size_t blocks_done)> progress;
};

class SystemTop : public sc_core::sc_module {
 public:
  SystemTop(sc_core::sc_module_name name, const SystemSetup& setup, FrameSource source,
            const tape::Program& program);
  ~SystemTop() override;

  // Call after sc_start(SC_ZERO_TIME): opens the VCD before the reset edge when the window
  // starts at cycle 0.
  void start();
  // Call after the simulation stopped: closes the VCD if it is still open.
  void finish();

  PlayMonitor& monitor() { return monitor_; }
  const TapeReaderModule& reader() const { return reader_; }
  bool limit_reached() const { return limit_reached_; }
  bool vcd_started() const { return vcd_open_ || vcd_closed_; }
  uint64_t cycle() const { return cycle_; }

 private:
  void falling_edge();
  InterpOutputs sample() const;

  SystemSetup setup_;
  sc_core::sc_clock clk_;
  InterpSignals signals_;
  TapeReaderModule reader_;
  std::unique_ptr<Engine> engine_;
  PlayMonitor monitor_;
  uint64_t cycle_ = 0;
  bool vcd_open_ = false, vcd_closed_ = false;
  bool limit_reached_ = false;
};

}  // namespace ncinterp::system
