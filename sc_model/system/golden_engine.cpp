// The golden engine: GoldenInterpModule plus SystemC's own VCD tracer over its ports,
// named and sized like the RTL's ports in Verilator's VCD (see engine.h).
#include <systemc>

#include "engine.h"
#include "golden_module.h"

namespace ncinterp::system {

namespace {

class GoldenEngine : public Engine {
 public:
  GoldenEngine(const InterpConfig& cfg, sc_core::sc_signal_in_if<bool>& clk, InterpSignals& s)
      : cfg_(cfg), clk_(clk), s_(s), module_("interp", cfg) {
    bind_engine(module_, clk, s);
  }
  ~GoldenEngine() override { close_vcd(); }

  void open_vcd(const std::string& path) override {
    close_vcd();
    // sc_create_vcd_trace_file appends ".vcd" itself.
    const std::string base =
        path.size() > 4 && path.compare(path.size() - 4, 4, ".vcd") == 0 ? path.substr(0, path.size() - 4)
                                                                          : path;
    file_ = sc_core::sc_create_vcd_trace_file(base.c_str());
    file_->set_time_unit(1, sc_core::SC_PS);  // Verilator's VCD is in ps as well
    const std::string p = "interp.interp_top.";
    sc_core::sc_trace(file_, clk_, p + "clk_i");
    sc_core::sc_trace(file_, s_.rst_ni, p + "rst_ni");
    trace(s_.feed_modulus_i, p + "feed_modulus_i", cfg_.modulus_width);
    trace(s_.frame_i, p + "frame_i", 8);
    sc_core::sc_trace(file_, s_.frame_valid_i, p + "frame_valid_i");
    sc_core::sc_trace(file_, s_.tape_end_i, p + "tape_end_i");
    sc_core::sc_trace(file_, s_.frame_ready_o, p + "frame_ready_o");
    sc_core::sc_trace(file_, s_.step_x_o, p + "step_x_o");
    sc_core::sc_trace(file_, s_.dir_x_o, p + "dir_x_o");
    sc_core::sc_trace(file_, s_.step_y_o, p + "step_y_o");
    sc_core::sc_trace(file_, s_.dir_y_o, p + "dir_y_o");
    trace(s_.pos_x_o, p + "pos_x_o", cfg_.pos_width);
    trace(s_.pos_y_o, p + "pos_y_o", cfg_.pos_width);
    trace(s_.block_n_o, p + "block_n_o", cfg_.seq_width);
    sc_core::sc_trace(file_, s_.busy_o, p + "busy_o");
    sc_core::sc_trace(file_, s_.done_o, p + "done_o");
    sc_core::sc_trace(file_, s_.error_o, p + "error_o");
    trace(s_.error_code_o, p + "error_code_o", 4);
    trace(s_.error_block_o, p + "error_block_o", cfg_.seq_width);
    trace(s_.error_offset_o, p + "error_offset_o", cfg_.offset_width);
    sc_core::sc_trace(file_, s_.feed_saturated_o, p + "feed_saturated_o");
  }

  void close_vcd() override {
    if (!file_) return;
    sc_core::sc_close_vcd_trace_file(file_);
    file_ = nullptr;
  }

 private:
  // Multi-bit ports with the RTL's width (the signal's value is stable storage).
  template <class T>
  void trace(const sc_core::sc_signal<T>& sig, const std::string& name, unsigned width) {
    sc_core::sc_trace(file_, sig.read(), name, static_cast<int>(width));
  }

  InterpConfig cfg_;
  sc_core::sc_signal_in_if<bool>& clk_;
  InterpSignals& s_;
  GoldenInterpModule module_;
  sc_core::sc_trace_file* file_ = nullptr;
};

}  // namespace

std::unique_ptr<Engine> make_golden_engine(const InterpConfig& cfg,
                                           sc_core::sc_signal_in_if<bool>& clk,
                                           InterpSignals& signals) {
  return std::make_unique<GoldenEngine>(cfg, clk, signals);
}

}  // namespace ncinterp::system
