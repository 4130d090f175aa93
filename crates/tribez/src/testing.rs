//! Helpers shared by the unit tests (compiled only for tests).

use num_rational::BigRational;

use crate::number::parse_rational;
use crate::patch::ControlNet;

/// An exact number from its text.
pub fn q(text: &str) -> BigRational {
    parse_rational(text).expect("test numbers parse")
}

/// A list of exact numbers from their texts.
pub fn r(v: &[&str]) -> Vec<BigRational> {
    v.iter().map(|t| q(t)).collect()
}

/// Numbers as their lowest-terms texts.
pub fn s(p: &[BigRational]) -> Vec<String> {
    p.iter().map(ToString::to_string).collect()
}

/// Finn's worked example: the quadratic net of Finn, Day 30, §30.1.
pub fn finn() -> ControlNet<BigRational> {
    let pts: Vec<Vec<BigRational>> = [
        [0, 0, 0],
        [1, 0, 2],
        [0, 2, 0],
        [0, 1, 0],
        [1, 1, 1],
        [0, 2, 1],
    ]
    .iter()
    .map(|p| {
        p.iter()
            .map(|&x| BigRational::from_integer(x.into()))
            .collect()
    })
    .collect();
    ControlNet::from_points(2, 2, &pts)
}
