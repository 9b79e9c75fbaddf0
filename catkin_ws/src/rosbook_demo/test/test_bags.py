"""finish_bag: the run's bag replaces an earlier run's only when the run completed."""

from rosbook_demo.bags import finish_bag, partial_bag


def folder_with_earlier_bag(tmp_path):
    bag = tmp_path / "office.bag"
    bag.write_bytes(b"earlier complete run")
    return bag


def test_the_run_records_beside_the_bag(tmp_path):
    assert partial_bag(tmp_path / "office.bag") == tmp_path / "office.partial.bag"


def test_a_completed_run_moves_its_bag_into_place(tmp_path):
    bag = folder_with_earlier_bag(tmp_path)
    partial_bag(bag).write_bytes(b"this run")
    assert finish_bag(bag, completed=True) is None
    assert bag.read_bytes() == b"this run"
    assert not partial_bag(bag).exists()


def test_an_interrupted_run_keeps_the_earlier_bag(tmp_path):
    bag = folder_with_earlier_bag(tmp_path)
    partial_bag(bag).write_bytes(b"half a run")
    kept = finish_bag(bag, completed=False)
    assert kept == (
        "the run did not finish: office.bag from an earlier run is kept; this run's "
        "incomplete recording is office.partial.bag"
    )
    assert bag.read_bytes() == b"earlier complete run"


def test_a_recording_never_closed_is_not_moved_even_when_the_run_completed(tmp_path):
    bag = folder_with_earlier_bag(tmp_path)
    active = tmp_path / "office.partial.bag.active"
    active.write_bytes(b"unindexed")
    kept = finish_bag(bag, completed=True)
    assert kept.startswith("its recording was not closed: office.bag from an earlier run")
    assert "office.partial.bag.active" in kept
    assert bag.read_bytes() == b"earlier complete run"


def test_a_first_run_interrupted_says_no_bag_was_written(tmp_path):
    assert finish_bag(tmp_path / "office.bag", completed=False) == (
        "the run did not finish: no office.bag was written"
    )
