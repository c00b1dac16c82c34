"""The construction kernel: geometry values, drawn curves and areas, the op table, protocols, instruments.

Layers, each importing only those before it:
``errors`` ← ``geometry`` ← ``curves``, ``areas``, ``rules``, ``trial`` ← ``ops`` ←
``protocol`` ← ``instruments`` (the Builder) ← ``figure``, ``division``, ``proportional``.
Nothing in the kernel imports anything outside it at module level.
"""
