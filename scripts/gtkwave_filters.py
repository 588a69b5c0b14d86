#!/usr/bin/env python3
"""Writes the GTKWave translate filter files of waves/ (used by waves/interp.gtkw).

Idea: a tape is text, so the waves should show it as text. frame_char.gtkwf names every
8-bit frame by its character (bit 7 is the even-parity bit, stripped; a frame with odd
parity is marked "!"); decoder_state.gtkwf and error_code.gtkwf name the decoder's states
and the error codes. The names are read from their one source (rtl/tape_decoder.sv's state
enum, sw/host/tape/tape_errors.def), never typed twice.
Values are written in hex, as the traces are displayed (@22 + translate).
Run from anywhere:  scripts/gtkwave_filters.py
"""
import pathlib
import re

root = pathlib.Path(__file__).resolve().parent.parent
waves = root / "waves"

NAMES = {0x0A: "LF", 0x0D: "CR", 0x20: "SP", 0x00: "NUL", 0x7F: "DEL"}


def frame_name(value: int) -> str:
    char = value & 0x7F
    parity_ok = bin(value).count("1") % 2 == 0
    text = NAMES.get(char) or (chr(char) if 0x21 <= char <= 0x7E else f"^{char:02X}")
    return text if parity_ok else text + "!"


def write(name: str, rows, width_digits: int) -> None:
    lines = [f"{value:0{width_digits}X} {text}" for value, text in rows]
    (waves / name).write_text("\n".join(lines) + "\n")


write("frame_char.gtkwf", [(v, frame_name(v)) for v in range(256)], 2)

states = re.findall(r"\bSt(\w+)\s*=\s*3'd(\d+)", (root / "rtl/tape_decoder.sv").read_text())
write("decoder_state.gtkwf", [(int(v), n.upper()) for n, v in states], 1)

errors = re.findall(r"^TAPE_ERROR\((\w+),\s*(\d+)", (root / "sw/host/tape/tape_errors.def").read_text(), re.M)
write("error_code.gtkwf", [(int(v), n) for n, v in errors], 1)
