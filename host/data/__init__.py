"""Data shipped with kinefuse (BROAD excerpt) and the script that cuts it."""
