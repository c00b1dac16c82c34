"""Seed 001, a machine-elements handbook (piston over-pressure, Tafel I): its printed numbers (:mod:`.printed`) and errata (:mod:`.errata`)."""
