"""Excerpt of the BROAD benchmark (CC BY 4.0): see README.md here.  A package only so that
its .npz/.json/.md files ship with kinefuse."""
