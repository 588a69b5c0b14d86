# Negative control of tape.interp_pkg_up_to_date: interp_pkg_gen --check must reject a copy
# of rtl/0_interp_pkg.sv with one error code changed, and say why.
# Usage: cmake -DGEN=interp_pkg_gen -DPKG=rtl/0_interp_pkg.sv -DOUT=scratch.sv -P this file
file(READ ${PKG} text)
string(REPLACE "ErrParity               = 5'd1," "ErrParity               = 5'd2," stale "${text}")
if(stale STREQUAL text)
  message(FATAL_ERROR "${PKG} has no ErrParity = 5'd1 to change")
endif()
file(WRITE ${OUT} "${stale}")
execute_process(COMMAND ${GEN} --check ${OUT} RESULT_VARIABLE rc ERROR_VARIABLE err)
if(rc EQUAL 0)
  message(FATAL_ERROR "interp_pkg_gen --check accepted a stale package")
endif()
if(NOT err MATCHES "out of date")
  message(FATAL_ERROR "interp_pkg_gen --check failed for another reason: ${err}")
endif()
