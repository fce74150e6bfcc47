"""Is the grader right? Mutants, alternates, the adversary, hints and the lab's verdicts (docs/grader-validity.md)."""
