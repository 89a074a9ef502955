"""Model / SIL / PIL harness: every registered filter through every loop, bit-compared.

* :mod:`.scenarios` — one scenario format (:class:`Case`) from the simulator and BROAD;
* :mod:`.loops` — model loop (reference, f32/q models), host C, generated C on QEMU M4F/M0
  (batch driver), and the firmware loops (:mod:`.firmware`: SIL over a pty, PIL in QEMU);
* :mod:`.compare` — bit-pattern comparison, first differing sample with its inputs;
* :mod:`.chunked` — runs carrying the state across pieces (re-chunking property);
* :mod:`.cost` — per-update instructions, flash and RAM of generated filters on M4F/M0;
* :mod:`.report` — ``kinefuse sil report`` (Markdown + PNG).
"""
