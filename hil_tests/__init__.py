"""kinefuse.hil_tests: motion/sensor simulator and the model / SIL / PIL harness."""
