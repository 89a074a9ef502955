"""Sub-commands of the kinefuse tool."""
