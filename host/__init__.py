"""kinefuse.host: the host tool (command line, data readers, stream decoding, benchmarks)."""
