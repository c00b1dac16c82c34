"""Files in and out: output folders written whole or not at all (:mod:`.staging`)."""
