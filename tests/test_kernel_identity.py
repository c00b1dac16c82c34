"""construct.kernel.identity: what is made once for an object, known by its identity."""

from construct.kernel.identity import by_identity


def test_made_once_per_object_and_never_for_an_equal_other():
    """An object asked again gets what was made for it, without making it again; an equal but other object (a
    copy of the list) gets its own, and a full store is emptied before a new object goes in."""
    made, calls = {}, []

    def make(obj):
        calls.append(obj)
        return len(calls)

    a, b = [1, 2], [1, 2]
    assert by_identity(made, a, make) == by_identity(made, a, make) == 1
    assert by_identity(made, b, make) == 2 and len(calls) == 2
    others = [[k] for k in range(3)]
    for o in others:
        by_identity(made, o, make, most=3)
    assert len(made) <= 3 and by_identity(made, others[-1], make, most=3) == 5 and len(calls) == 5
