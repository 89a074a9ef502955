"""kinefuse.firmware: C sources for the sensor units (generated filters under generated/)."""
