"""Seed 004, Baumann (1902), flywheel weights: printed numbers (:mod:`.printed`), errata (:mod:`.errata`), his coefficients (:mod:`.flywheel`) and error analysis (:mod:`.excess_error`)."""
