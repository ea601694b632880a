"""A 2D cloth: position Verlet plus iterative constraint relaxation (Jakobsen 2001).

The package is a restricted Python subset that runs under CPython and is transpiled by
Transcrypt into the JavaScript the page ships. `cloth.api` is the entry point for both.
"""
