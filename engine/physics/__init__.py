"""The equations: one function per equation of a seed or a standard, on floats or numpy arrays."""
