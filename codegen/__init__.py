"""kinefuse.codegen: estimators written once in Python, traced to an SSA graph, emitted as
float32 C, fixed-point C and bit-exact Python models of both."""
