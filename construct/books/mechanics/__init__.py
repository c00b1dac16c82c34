"""Seed 002, a mechanics text (§ 146–147, two cranks at 90°): its printed numbers (:mod:`.printed`) and errata (:mod:`.errata`)."""
