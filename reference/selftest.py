"""Checks of the reference itself, run by run.py before every run (a second of work).

* floats.py against the platform: Python's float() rounds a Fraction correctly to f64, and
  struct's f32 conversion of a double rounds correctly to f32; math.ulp and math.nextafter give
  the binade ULP and the neighbours of an f64.
* bezier.py against the worked examples of docs/theory.md: Finn's §3 example, the blossom of §4,
  Floater's Cramer example of §2, the pentagon's Wachspress coordinates of §12, the cubic Bernstein
  values of §1, and the ULP examples of §14.4.
* quadratic.py against math.sqrt (correctly rounded): RN(√j) and the verdicts of every
  tolerance against √j, and signs of a + b√D worked by hand.
"""

import math
import random
import struct
from fractions import Fraction as F

import bezier as bz
import floats


def check_floats(rng, n=2000):
    for _ in range(n):
        x = rng.uniform(-1, 1) * 2.0 ** rng.randint(-1074, 1000)
        q = F(x) + F(rng.randint(-10**6, 10**6), 10 ** rng.randint(1, 30)) * (F(x) if x else 1)
        try:
            r = float(q)
        except OverflowError:
            continue
        assert floats.rn(q, "f64") == F(r), ("rn f64", q)
        assert floats.ulp(F(r), "f64") == F(math.ulp(r)), ("ulp", r)
        assert floats.step(F(r), 1, "f64") == F(math.nextafter(r, math.inf)), ("step", r)
        assert floats.step(F(r), -1, "f64") == F(math.nextafter(r, -math.inf)), ("step", r)
        assert floats.parse(floats.hex_text(F(r), "f64")) == F(r)
        assert F(floats.exact_decimal(F(r))) == F(r)
        y = rng.uniform(-1, 1) * 2.0 ** rng.randint(-152, 126)
        z = struct.unpack("f", struct.pack("f", y))[0]
        assert floats.rn(F(y), "f32") == F(z), ("rn f32", y)
    # ties to even, the tie just below 2^1024 (rounds to infinity), underflow to zero
    assert floats.rn(F(2**53 + 1), "f64") == 2**53 and floats.rn(F(2**53 + 3), "f64") == 2**53 + 4
    assert floats.rn(F(1, 2**1075), "f64") == 0 and floats.rn(F(3, 2**1076), "f64") == F(1, 2**1074)
    try:
        floats.rn(F(2**1024 - 2**970), "f64")
        raise AssertionError("2^1024 - 2^970 must round to infinity")
    except OverflowError:
        pass
    # theory §14.4: |0.1 - 1/10| = 0.4 ulp(1/10); 0.1 + 0.2 is 0.8 ulp above 3/10, one step above RN
    assert abs(F(0.1) - F(1, 10)) / floats.ulp(F(1, 10), "f64") == F(2, 5)
    assert (F(0.1 + 0.2) - F(3, 10)) / floats.ulp(F(3, 10), "f64") == F(4, 5)
    assert floats.step(floats.rn(F(3, 10), "f64"), 1, "f64") == F(0.1 + 0.2)


def check_bezier():
    finn = {"n": 2, "m": 2, "weights": None, "points": {
        (2, 0, 0): [0, 0, 0], (1, 1, 0): [1, 0, 2], (0, 2, 0): [0, 2, 0],
        (1, 0, 1): [0, 1, 0], (0, 1, 1): [1, 1, 1], (0, 0, 2): [0, 2, 1]}}
    finn["points"] = {a: [F(x) for x in v] for a, v in finn["points"].items()}
    u = [F(1, 2), F(1, 3), F(1, 6)]
    assert bz.evaluate(finn, u) == [F(4, 9), F(5, 9), F(29, 36)]
    assert bz.blossom(finn, [[F(1, 2), F(1, 2), 0], [0, 0, 1]]) == [F(1, 2), 1, F(1, 2)]
    e1 = [1, 0, -1]
    assert bz.derivative(finn, u, [e1]) == [0, -2, F(1, 3)]  # p_x on the reference triangle
    T = [[F(1), F(2)], [F(7), F(3)], [F(2), F(8)]]
    assert bz.barycentric(T, [3, 4]) == [F(3, 7), F(2, 7), F(2, 7)]
    assert bz.directional(T, [1, -2]) == [F(1, 7), F(8, 35), F(-13, 35)]
    pent = [[F(x) for x in v] for v in [[0, 0], [4, 0], [5, 3], [2, 5], [-1, 3]]]
    assert bz.wachspress(pent, [2, 2]) == [F(81, 358), F(81, 358), F(33, 179), F(32, 179), F(33, 179)]
    cubic = [bz.bernstein(a, u) for a in bz.indices(3, 2)]
    assert cubic == [F(1, 8), F(1, 4), F(1, 6), F(1, 27), F(1, 8), F(1, 6), F(1, 18), F(1, 24), F(1, 36), F(1, 216)]
    assert [bz.multinomial(a) for a in bz.indices(3, 2)] == [1, 3, 3, 1, 3, 6, 3, 3, 3, 1]
    assert bz.elevate(finn, 1)[(2, 1, 0)] == [F(2, 3), 0, F(4, 3)]  # guide §5 elevate


def check_quadratic(rng, n=300):
    """quadratic.py against the platform: math.sqrt is correctly rounded (IEEE 754), so RN(√j)
    and its verdicts are known independently; signs of a + b√D by hand."""
    from quadratic import Quad, judge, rounded

    assert Quad(0, 1, 2).sign() == 1 and Quad(1, -1, 2).sign() == -1
    assert Quad(-3, 2, 2).sign() == -1 and Quad(-2, F(3, 2), 2).sign() == 1  # -3+2.83, -2+2.12
    assert Quad(F(3, 2), -1, 2).sign() == 1 and Quad(0, 0, 2).sign() == 0
    assert Quad(1, 1, 3) * Quad(1, -1, 3) == -2  # (1 + √3)(1 - √3)
    for _ in range(n):
        j = rng.randint(2, 10**6)
        if math.isqrt(j) ** 2 == j:
            continue
        x = Quad(0, 1, j)
        r = F(math.sqrt(j))
        assert rounded(x, "f64") == r, ("rn √", j)
        assert judge(r, x, "correctly_rounded", None, "f64")
        assert not judge(floats.step(r, 1, "f64"), x, "correctly_rounded", None, "f64")
        assert judge(r, x, "ulps", F(1, 2), "f64") and not judge(r, x, "exact", None, "f64")
        other = floats.step(r, 1 if r * r < j else -1, "f64")  # the float on x's other side
        assert judge(other, x, "faithful", None, "f64")
        assert not judge(floats.step(r, -1 if r * r < j else 1, "f64"), x, "faithful", None, "f64")
        err = abs(r * r - j) / (2 * r)  # about |r - √j|, to choose abs tolerances either side
        assert judge(r, x, "abs", 2 * err, None) and not judge(r, x, "abs", err / 2, None)
        assert judge(r, x, "rel", 2 * err / r, None) and not judge(r, x, "rel", err / (2 * r), None)


def run(seed=0):
    check_floats(random.Random(seed))
    check_bezier()
    check_quadratic(random.Random(seed))


if __name__ == "__main__":
    run()
    print("reference self-test: ok")
