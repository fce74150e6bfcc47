"""CI's own tools: its stage allowances, coverage, the syntax check of the sources it does not build."""
