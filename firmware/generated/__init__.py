"""Generated filters (C sources and their Python models)."""
