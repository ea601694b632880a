"""The benchmark: `python -m bench` (speed against error), `--physics`, `--figures`,
`--gestures`. CPython only, outside the transpiled package cloth/; it drives the shipped page."""
