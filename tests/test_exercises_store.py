"""course_lib.exercises._store: the variant rows' fingerprints packed and unpacked (issue 33)."""

import json

import pytest

from course_lib.exercises._store import FIELD, SLOT, Fingerprints, pack, unpack

D = ["0123456789abcdef", "fedcba9876543210", "00112233445566aa", "aabbccddeeff0011"]


def _record(value, mistake):
    """A record as instructor/build/exercise_fingerprints.py writes one (a transform and a
    digest)."""
    return {
        "size": 3,
        "value": [value],
        "mistakes": {
            "negated": {"transform": {"ops": ["neg", "neg", "neg"], "perm": "identity"}},
            "scalar_last": {"value": [mistake]},
        },
    }


def test_rows_of_one_shape_share_one_template_and_unpack_to_the_same_record():
    rows = [_record(D[0], D[1]), _record(D[2], D[3])]
    packed = pack(rows)
    assert len(packed["templates"]) == 1 and packed["rows"][1] == f"0 {D[3]} {D[2]}"
    assert [unpack(packed, i) for i in range(2)] == rows
    assert json.dumps(packed).count("identity") == 1  # what the rows share is stored once


def test_a_row_of_another_shape_gets_a_template_of_its_own():
    other = {"size": 3, "value": [D[0]], "mistakes": {"negated": {"value": [D[1]]}}}
    packed = pack([_record(D[0], D[1]), other])
    assert len(packed["templates"]) == 2 and unpack(packed, 1) == other


def test_a_record_holding_the_slot_itself_is_refused():
    with pytest.raises(ValueError, match="template slot"):
        pack([{"value": [SLOT]}])


def test_the_mapping_unpacks_name_at_k_and_knows_no_row_beyond_the_table():
    data = {"ex": _record(D[0], D[1]), FIELD: {"ex": pack([_record(D[2], D[3])])}}
    stored = Fingerprints(data)
    assert stored["ex"] == data["ex"] and stored["ex@1"] == _record(D[2], D[3])
    assert list(stored) == ["ex", "ex@1"] and len(stored) == 2
    for missing in ("ex@2", "ex@0", "ex@x", "other@1", "other"):
        with pytest.raises(KeyError):
            stored[missing]
