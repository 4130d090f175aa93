//! Subdivision, halving, subpatches and degree elevation of a degree-30 triangle, exactly.
//! `cargo bench --bench constructions`.
//!
//! Each construction is written once, generic over the number type; for `BigRational` it runs a
//! specialised integer kernel (homogeneous integer arithmetic, one gcd per result). The
//! "generic code" rows run the same constructions on `Plain`, a wrapper of `BigRational` the
//! kernels do not recognise, i.e. the generic code on exact rationals: the kernel is kept
//! only because these rows show it faster.

use criterion::{Criterion, criterion_group, criterion_main};
use num_rational::BigRational;
use tribez::hazmat::blossom::subpatch;
use tribez::hazmat::elevate::elevate;
use tribez::hazmat::patch::ControlNet;
use tribez::hazmat::simplex::Simplex;
use tribez::hazmat::subdivide::{halve, midpoint_split, split_at_pieces};

/// `BigRational` under another name: the constructions run their generic code on it.
#[derive(Clone, Debug, PartialEq)]
struct Plain(BigRational);

macro_rules! plain_ops {
    ($($trait:ident $method:ident),*) => {$(
        impl std::ops::$trait for Plain {
            type Output = Plain;
            fn $method(self, o: Plain) -> Plain {
                Plain(std::ops::$trait::$method(self.0, o.0))
            }
        }
        impl<'a> std::ops::$trait<&'a Plain> for Plain {
            type Output = Plain;
            fn $method(self, o: &'a Plain) -> Plain {
                Plain(std::ops::$trait::$method(self.0, &o.0))
            }
        }
    )*};
}
plain_ops!(Add add, Sub sub, Mul mul, Div div);

impl std::ops::Neg for Plain {
    type Output = Plain;
    fn neg(self) -> Plain {
        Plain(-self.0)
    }
}
impl num_traits::Zero for Plain {
    fn zero() -> Self {
        Plain(BigRational::zero())
    }
    fn is_zero(&self) -> bool {
        self.0.is_zero()
    }
}
impl num_traits::One for Plain {
    fn one() -> Self {
        Plain(BigRational::one())
    }
}
impl tribez::hazmat::scalar::Scalar for Plain {
    fn from_u64(k: u64) -> Self {
        Plain(BigRational::from_integer(k.into()))
    }
    fn from_biguint(k: &num_bigint::BigUint) -> Self {
        Plain(BigRational::from_integer(k.clone().into()))
    }
}

fn plain(net: &ControlNet<BigRational>) -> ControlNet<Plain> {
    net.map(|x| Plain(x.clone()))
}

fn q(a: i64, b: i64) -> BigRational {
    BigRational::new(a.into(), b.into())
}

/// A degree-n triangle in R^3 with small pseudo-random rational coordinates.
fn net(n: usize) -> ControlNet<BigRational> {
    let sx = Simplex::new(2, n);
    let mut state: u64 = 12345;
    let coords = (0..sx.len() * 3)
        .map(|_| {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            q(
                ((state >> 33) % 199) as i64 - 99,
                ((state >> 20) % 16) as i64 + 1,
            )
        })
        .collect();
    ControlNet::new(sx, 3, coords)
}

fn constructions(c: &mut Criterion) {
    let n30 = net(30);
    let t = [q(1, 3), q(1, 5), q(7, 15)];
    let f = [
        vec![q(1, 3), q(1, 3), q(1, 3)],
        vec![q(2, 1), q(-1, 1), q(0, 1)],
        vec![q(1, 7), q(3, 7), q(3, 7)],
    ];
    c.bench_function("degree 30: split at a point", |b| {
        b.iter(|| split_at_pieces(&n30, &t).unwrap())
    });
    c.bench_function("degree 30: four-way midpoint split", |b| {
        b.iter(|| midpoint_split(&n30).unwrap())
    });
    c.bench_function("degree 30: halve", |b| b.iter(|| halve(&n30, 0, 1)));
    c.bench_function("degree 30: subpatch", |b| {
        b.iter(|| subpatch(&n30, &f).unwrap())
    });
    c.bench_function("degree 30: elevate by 1", |b| b.iter(|| elevate(&n30, 1)));
    // The same constructions through the generic code on exact rationals.
    let p30 = plain(&n30);
    let pt: Vec<Plain> = t.iter().cloned().map(Plain).collect();
    let pf: Vec<Vec<Plain>> = f
        .iter()
        .map(|v| v.iter().cloned().map(Plain).collect())
        .collect();
    c.bench_function("degree 30: split at a point, generic code", |b| {
        b.iter(|| split_at_pieces(&p30, &pt).unwrap())
    });
    c.bench_function("degree 30: subpatch, generic code", |b| {
        b.iter(|| subpatch(&p30, &pf).unwrap())
    });
    c.bench_function("degree 30: elevate by 1, generic code", |b| {
        b.iter(|| elevate(&p30, 1))
    });
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(10);
    targets = constructions
}
criterion_main!(benches);
