"""kinefuse bench ... benchmarks."""
