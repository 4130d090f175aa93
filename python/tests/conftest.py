import pathlib
import sys

import pytest

HERE = pathlib.Path(__file__).resolve().parent
ROOT = HERE.parent.parent
sys.path.insert(0, str(HERE))


@pytest.fixture
def root():
    return ROOT


@pytest.fixture
def finn():
    import tribez

    # Finn's notes, Day 30, the worked example: 200:(0,0,0) 110:(1,0,2) 020:(0,2,0)
    # 101:(0,1,0) 011:(1,1,1) 002:(0,2,1), in bezier's layout (one column per control point)
    return tribez.Patch.from_nodes(
        [[0, 1, 0, 0, 1, 0], [0, 0, 2, 1, 1, 2], [0, 2, 0, 0, 1, 1]]
    )
