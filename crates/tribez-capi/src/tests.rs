//! Tests of the C ABI, calling the extern functions as C does: every function, every error path
//! (NULL pointers, bad tolerances, wrong sizes, non-finite numbers), reports byte-identical to
//! the command line's, a panic reported as an error, concurrent use.
//!
//! Expected values come from tests/derive.py (Python fractions, no tribez) or from hand
//! derivations written beside them; reports are compared with the `tribez` binary's output.

use std::ffi::{CStr, CString, c_char};
use std::path::{Path, PathBuf};
use std::ptr::{null, null_mut};

use super::*;

/// Finn's quadratic triangle in R^3, control points 200, 110, 020, 101, 011, 002.
const FINN: [f64; 18] = [
    0., 0., 0., 1., 0., 2., 0., 2., 0., 0., 1., 0., 1., 1., 1., 0., 2., 1.,
];

const FINN_TOML: &str = "degree = 2
[control_points]
\"2,0,0\" = [\"0\", \"0\", \"0\"]
\"1,1,0\" = [\"1\", \"0\", \"2\"]
\"0,2,0\" = [\"0\", \"2\", \"0\"]
\"1,0,1\" = [\"0\", \"1\", \"0\"]
\"0,1,1\" = [\"1\", \"1\", \"1\"]
\"0,0,2\" = [\"0\", \"2\", \"1\"]
";

fn finn() -> *mut tribez_patch {
    let p = unsafe { tribez_patch_from_f64(2, 2, 3, FINN.as_ptr(), null_mut()) };
    assert!(!p.is_null());
    p
}

/// The message and code of an error, which is freed.
fn take(err: *mut tribez_error) -> (c_int, String) {
    assert!(!err.is_null(), "an error was expected");
    let code = unsafe { tribez_error_code(err) };
    let msg = unsafe { CStr::from_ptr(tribez_error_message(err)) }
        .to_str()
        .unwrap()
        .to_string();
    unsafe { tribez_error_free(err) };
    assert!(!msg.contains('\n'), "{msg}");
    (code, msg)
}

fn taken_string(s: *mut c_char) -> String {
    assert!(!s.is_null());
    let out = unsafe { CStr::from_ptr(s) }.to_str().unwrap().to_string();
    unsafe { tribez_string_free(s) };
    out
}

fn eval_exact(p: *const tribez_patch, point: &[&str]) -> Result<Vec<String>, (c_int, String)> {
    let cs: Vec<CString> = point.iter().map(|s| CString::new(*s).unwrap()).collect();
    let ptrs: Vec<*const c_char> = cs.iter().map(|c| c.as_ptr()).collect();
    let (mut values, mut len, mut err) = (null_mut(), 0usize, null_mut());
    let code = unsafe {
        tribez_eval_exact(
            p,
            ptrs.as_ptr(),
            ptrs.len(),
            &mut values,
            &mut len,
            &mut err,
        )
    };
    if code != TRIBEZ_OK {
        return Err(take(err));
    }
    assert!(err.is_null());
    let out = (0..len)
        .map(|i| {
            unsafe { CStr::from_ptr(*values.add(i)) }
                .to_str()
                .unwrap()
                .to_string()
        })
        .collect();
    unsafe { tribez_strings_free(values, len) };
    Ok(out)
}

fn eval_cr(
    p: *const tribez_patch,
    point: &[f64],
    out_len: usize,
) -> Result<Vec<f64>, (c_int, String)> {
    let mut out = vec![-7.0; out_len];
    let mut err = null_mut();
    let code = unsafe {
        tribez_eval_f64_correctly_rounded(
            p,
            point.as_ptr(),
            point.len(),
            out.as_mut_ptr(),
            out_len,
            &mut err,
        )
    };
    if code != TRIBEZ_OK {
        assert!(out.iter().all(|&x| x == -7.0), "out untouched on failure");
        return Err(take(err));
    }
    Ok(out)
}

struct Opts {
    opts: tribez_check_options,
    _names: Vec<CString>,
}

fn opts(first_row: usize, results: Option<&str>, patch: Option<&str>, cartesian: bool) -> Opts {
    let r = results.map(|s| CString::new(s).unwrap());
    let p = patch.map(|s| CString::new(s).unwrap());
    let opts = tribez_check_options {
        cartesian,
        algorithm: TRIBEZ_ALGORITHM_CASTELJAU,
        first_row,
        results_name: r.as_ref().map_or(null(), |c| c.as_ptr()),
        patch_name: p.as_ref().map_or(null(), |c| c.as_ptr()),
    };
    Opts {
        opts,
        _names: r.into_iter().chain(p).collect(),
    }
}

fn check64(
    p: *const tribez_patch,
    points: &[f64],
    values: &[f64],
    rows: usize,
    tolerance: &str,
    o: Option<&tribez_check_options>,
) -> Result<*mut tribez_report, (c_int, String)> {
    let t = CString::new(tolerance).unwrap();
    let (mut out, mut err) = (null_mut(), null_mut());
    let code = unsafe {
        tribez_check_f64(
            p,
            points.as_ptr(),
            values.as_ptr(),
            rows,
            t.as_ptr(),
            o.map_or(null(), |o| o as *const _),
            &mut out,
            &mut err,
        )
    };
    if code != TRIBEZ_OK {
        assert!(out.is_null());
        let (c, m) = take(err);
        assert_eq!(c, code);
        return Err((c, m));
    }
    assert!(err.is_null() && !out.is_null());
    Ok(out)
}

// --- patches and evaluation -----------------------------------------------------------------

#[test]
fn exact_values_of_finn() {
    let p = finn();
    // derive.py (and by hand: u² = 1/4, 2uv = 1/3, v² = 1/9, 2uw = 1/6, 2vw = 1/9, w² = 1/36,
    // so x = 1/3 + 1/9 = 4/9)
    assert_eq!(
        eval_exact(p, &["1/2", "1/3", "1/6"]).unwrap(),
        ["4/9", "5/9", "29/36"]
    );
    // (1/2, 1/4, 1/4): x = 2uv + 2vw = 1/4 + 1/8 = 3/8; y = 5/8; z = 11/16; and decimal input
    assert_eq!(
        eval_exact(p, &["0.5", "1/4", "0.25"]).unwrap(),
        ["3/8", "5/8", "11/16"]
    );
    // an integer value is "p"
    assert_eq!(eval_exact(p, &["1", "0", "0"]).unwrap(), ["0", "0", "0"]);
    unsafe {
        assert_eq!(tribez_patch_simplex_dim(p), 2);
        assert_eq!(tribez_patch_degree(p), 2);
        assert_eq!(tribez_patch_dimension(p), 3);
        assert_eq!(tribez_patch_point_len(p), 3);
        assert_eq!(tribez_patch_simplex_dim(null()), 0);
        assert_eq!(tribez_patch_degree(null()), 0);
        assert_eq!(tribez_patch_dimension(null()), 0);
        assert_eq!(tribez_patch_point_len(null()), 0);
        tribez_patch_free(p);
        tribez_patch_free(null_mut());
    }
}

#[test]
fn correctly_rounded_values() {
    let p = finn();
    // derive.py: the homogeneous form at the doubles (0.5, 0.1, 0.4), which sum to more than 1
    let hex = |s: &str| -> f64 {
        // 0x1.HHHHHHHHHHHHHp±E
        let (mant, exp) = s.trim_start_matches("0x").split_once('p').unwrap();
        let (int, frac) = mant.split_once('.').unwrap();
        let bits = u64::from_str_radix(&format!("{int}{frac}"), 16).unwrap() as f64;
        bits * 2f64.powi(exp.parse::<i32>().unwrap() - 4 * frac.len() as i32)
    };
    let want = [
        "0x1.70a3d70a3d70bp-3",
        "0x1.a3d70a3d70a3ep-1",
        "0x1.c28f5c28f5c2ap-2",
    ]
    .map(hex);
    assert_eq!(eval_cr(p, &[0.5, 0.1, 0.4], 3).unwrap(), want);
    // derive.py: a point where a double de Casteljau is one ULP below in x
    let point = [
        "0x1.4b9ad0f953a6ep-2",
        "0x1.a1c9fc3f7ecf9p-4",
        "0x1.25f957fb6652ap-1",
    ]
    .map(hex);
    let want = [
        "0x1.772cc1cd2fd97p-3",
        "0x1.2b4cff49b0316p+0",
        "0x1.286858af58595p-1",
    ]
    .map(hex);
    assert_eq!(eval_cr(p, &point, 3).unwrap(), want);
    // dyadic: exact
    assert_eq!(
        eval_cr(p, &[0.5, 0.25, 0.25], 3).unwrap(),
        [0.375, 0.625, 0.6875]
    );
    unsafe { tribez_patch_free(p) };
}

#[test]
fn the_documented_canonical_order_is_the_patch_files() {
    // a cubic with control point number i (in the order the header documents) equal to i:
    // the patch file names each by its multi-index
    let order = [
        "3,0,0", "2,1,0", "1,2,0", "0,3,0", "2,0,1", "1,1,1", "0,2,1", "1,0,2", "0,1,2", "0,0,3",
    ];
    let mut toml = String::from("degree = 3\n[control_points]\n");
    for (i, a) in order.iter().enumerate() {
        toml += &format!("\"{a}\" = [\"{i}\"]\n");
    }
    let net: Vec<f64> = (0..10).map(f64::from).collect();
    let from_f64 = unsafe { tribez_patch_from_f64(2, 3, 1, net.as_ptr(), null_mut()) };
    let (t, f) = (CString::new(toml).unwrap(), c"toml");
    let mut err = null_mut();
    let from_text = unsafe { tribez_patch_from_text(t.as_ptr(), f.as_ptr(), &mut err) };
    assert!(!from_text.is_null() && !from_f64.is_null());
    for point in [
        ["1/5", "1/3", "7/15"],
        ["1", "0", "0"],
        ["0", "1/2", "1/2"],
        ["-1", "3/2", "1/2"],
    ] {
        assert_eq!(eval_exact(from_f64, &point), eval_exact(from_text, &point));
    }
    // and by hand at a vertex: (0, 0, 1) is control point 003, number 9
    assert_eq!(eval_exact(from_f64, &["0", "0", "1"]).unwrap(), ["9"]);
    assert_eq!(eval_exact(from_f64, &["0", "1", "0"]).unwrap(), ["3"]);
    unsafe {
        tribez_patch_free(from_f64);
        tribez_patch_free(from_text);
    }
}

fn from_f64_err(m: usize, n: usize, d: usize, xs: *const f64) -> String {
    let mut err = null_mut();
    let p = unsafe { tribez_patch_from_f64(m, n, d, xs, &mut err) };
    assert!(p.is_null());
    take(err).1
}

#[test]
fn patch_from_f64_errors() {
    let xs = [0.0; 64];
    assert_eq!(
        from_f64_err(0, 2, 3, xs.as_ptr()),
        "m: 0 is not a simplex dimension (1 to 16)"
    );
    assert_eq!(
        from_f64_err(17, 1, 1, xs.as_ptr()),
        "m: 17 is not a simplex dimension (1 to 16)"
    );
    assert_eq!(
        from_f64_err(2, 201, 1, xs.as_ptr()),
        "degree: 201 is above the limit of 200"
    );
    assert!(from_f64_err(2, 2, 0, xs.as_ptr()).starts_with("d: 0 coordinates"));
    // C(216, 16) control points: refused before reading any
    assert!(from_f64_err(16, 200, 1, xs.as_ptr()).contains("more than 250000 control points"));
    // 250,000 control points of usize::MAX / 2 coordinates: the size overflows, nothing is read
    assert!(from_f64_err(1, 1, usize::MAX / 2, xs.as_ptr()).contains("pass the largest size"));
    assert_eq!(
        from_f64_err(2, 2, 3, null()),
        "control_points: NULL pointer"
    );
    let mut bad = FINN;
    bad[13] = f64::NAN;
    assert_eq!(
        from_f64_err(2, 2, 3, bad.as_ptr()),
        "control_points[13] (control point 4, coordinate 1): NaN has no exact value"
    );
    bad[13] = f64::NEG_INFINITY;
    assert!(from_f64_err(2, 2, 3, bad.as_ptr()).ends_with(": -infinity has no exact value"));
    // the status of a NULL err is the return value alone
    assert!(unsafe { tribez_patch_from_f64(0, 2, 3, xs.as_ptr(), null_mut()) }.is_null());
}

fn from_text_err(text: *const c_char, format: *const c_char) -> String {
    let mut err = null_mut();
    assert!(unsafe { tribez_patch_from_text(text, format, &mut err) }.is_null());
    take(err).1
}

#[test]
fn patch_from_text_and_file_errors() {
    let finn = CString::new(FINN_TOML).unwrap();
    assert_eq!(
        from_text_err(null(), c"toml".as_ptr()),
        "text: NULL pointer"
    );
    assert_eq!(from_text_err(finn.as_ptr(), null()), "format: NULL pointer");
    assert_eq!(
        from_text_err(finn.as_ptr(), c"xml".as_ptr()),
        "format: `xml` is not a patch format (expected \"toml\" or \"json\")"
    );
    assert!(from_text_err(c"degree = = 2".as_ptr(), c"toml".as_ptr()).contains("invalid TOML"));
    assert!(from_text_err(c"{".as_ptr(), c"json".as_ptr()).contains("<json>"));
    let bad = CString::new(FINN_TOML.replace("degree = 2", "degree = 201")).unwrap();
    assert!(from_text_err(bad.as_ptr(), c"toml".as_ptr()).contains("above the limit of 200"));
    // not UTF-8
    assert!(
        from_text_err(c"degree = \xff".as_ptr(), c"toml".as_ptr())
            .starts_with("text: not valid UTF-8")
    );

    let mut err = null_mut();
    assert!(unsafe { tribez_patch_from_file(null(), &mut err) }.is_null());
    assert_eq!(take(err), (TRIBEZ_ERROR_NULL, "path: NULL pointer".into()));
    let dir = scratch("from_file");
    let good = dir.join("finn.toml");
    std::fs::write(&good, FINN_TOML).unwrap();
    let path = CString::new(good.to_str().unwrap()).unwrap();
    err = null_mut(); // the one taken above is freed
    let p = unsafe { tribez_patch_from_file(path.as_ptr(), &mut err) };
    assert!(!p.is_null() && err.is_null());
    assert_eq!(
        eval_exact(p, &["1/2", "1/3", "1/6"]).unwrap(),
        ["4/9", "5/9", "29/36"]
    );
    unsafe { tribez_patch_free(p) };
}

/// The one-line messages are the command line's (`tribez: MESSAGE` on its standard error).
#[test]
fn error_messages_are_the_command_lines() {
    let dir = scratch("messages");
    let rows = dir.join("rows.csv");
    std::fs::write(&rows, "0.5,0.25,0.25,0.375,0.625,0.6875\n").unwrap();
    let cases = [
        ("missing.toml", None),
        (
            "bad.toml",
            Some(FINN_TOML.replace("\"1\", \"1\", \"1\"", "\"1\", \"x\", \"1\"")),
        ),
        (
            "big.toml",
            Some(FINN_TOML.replace("degree = 2", "degree = 3")),
        ),
        ("empty.json", Some(String::new())),
        ("p.txt", Some(FINN_TOML.to_string())),
    ];
    for (name, text) in cases {
        let path = dir.join(name);
        if let Some(t) = text {
            std::fs::write(&path, t).unwrap();
        }
        let c = CString::new(path.to_str().unwrap()).unwrap();
        let mut err = null_mut();
        assert!(unsafe { tribez_patch_from_file(c.as_ptr(), &mut err) }.is_null());
        let (code, msg) = take(err);
        assert_eq!(code, TRIBEZ_ERROR_INPUT);
        let out = cli(&[
            "check",
            "--patch",
            path.to_str().unwrap(),
            "--results",
            rows.to_str().unwrap(),
        ]);
        assert_eq!(out.status.code(), Some(2));
        assert_eq!(
            String::from_utf8_lossy(&out.stderr),
            format!("tribez: {msg}\n"),
            "{name}"
        );
    }
    // the tolerance: the CLI names its flag, the C ABI its argument
    let p = finn();
    let (_, msg) = check64(
        p,
        &[0.5, 0.25, 0.25],
        &[0.375, 0.625, 0.6875],
        1,
        "ulps=x",
        None,
    )
    .unwrap_err();
    let patch = dir.join("finn.toml");
    std::fs::write(&patch, FINN_TOML).unwrap();
    let out = cli(&[
        "check",
        "--patch",
        patch.to_str().unwrap(),
        "--results",
        rows.to_str().unwrap(),
        "--precision",
        "f64",
        "--tolerance",
        "ulps=x",
    ]);
    assert_eq!(
        String::from_utf8_lossy(&out.stderr),
        format!("tribez: --{msg}\n")
    );
    unsafe { tribez_patch_free(p) };
}

#[test]
fn eval_errors() {
    let p = finn();
    let e = |r: Result<Vec<String>, (c_int, String)>| r.unwrap_err();
    assert_eq!(
        e(eval_exact(null(), &["1", "0", "0"])),
        (TRIBEZ_ERROR_NULL, "patch: NULL pointer".into())
    );
    assert_eq!(
        e(eval_exact(p, &["1", "0"])).1,
        "point: 2 coordinates, but a point of this patch has 3"
    );
    assert!(
        e(eval_exact(p, &["1", "x", "0"]))
            .1
            .starts_with("point[1]: `x`: ")
    );
    assert!(
        e(eval_exact(p, &["1/2", "1/2", "1/2"])).1.contains("sum"),
        "{:?}",
        eval_exact(p, &["1/2", "1/2", "1/2"])
    );
    let (mut values, mut len, mut err) = (null_mut(), 0usize, null_mut());
    let one = [c"1".as_ptr(), null(), c"0".as_ptr()];
    unsafe {
        assert_eq!(
            tribez_eval_exact(p, null(), 3, &mut values, &mut len, &mut err),
            TRIBEZ_ERROR_NULL
        );
        assert_eq!(take(err).1, "point: NULL pointer");
        assert_eq!(
            tribez_eval_exact(p, one.as_ptr(), 3, &mut values, &mut len, &mut err),
            TRIBEZ_ERROR_NULL
        );
        assert_eq!(take(err).1, "point[1]: NULL pointer");
        assert_eq!(
            tribez_eval_exact(p, one.as_ptr(), 3, null_mut(), &mut len, &mut err),
            TRIBEZ_ERROR_NULL
        );
        assert_eq!(take(err).1, "values: NULL pointer");
        assert_eq!(
            tribez_eval_exact(p, one.as_ptr(), 3, &mut values, null_mut(), &mut err),
            TRIBEZ_ERROR_NULL
        );
        assert_eq!(take(err).1, "values_len: NULL pointer");
        assert!(values.is_null() && len == 0);
        tribez_strings_free(null_mut(), 0);
    }
    let e = |r: Result<Vec<f64>, (c_int, String)>| r.unwrap_err();
    assert_eq!(
        e(eval_cr(null(), &[1.0, 0.0, 0.0], 3)).1,
        "patch: NULL pointer"
    );
    assert_eq!(
        e(eval_cr(p, &[1.0, 0.0], 3)).1,
        "point: 2 coordinates, but a point of this patch has 3"
    );
    assert_eq!(
        e(eval_cr(p, &[1.0, 0.0, 0.0], 2)).1,
        "out: room for 2 values, but the patch's points have 3 coordinates"
    );
    assert_eq!(
        e(eval_cr(p, &[1.0, f64::NAN, 0.0], 3)).1,
        "point[1]: NaN has no exact value"
    );
    assert_eq!(
        e(eval_cr(p, &[f64::INFINITY, 0.0, 0.0], 3)).1,
        "point[0]: infinity has no exact value"
    );
    let mut err = null_mut();
    let mut out = [0.0; 3];
    unsafe {
        assert_eq!(
            tribez_eval_f64_correctly_rounded(p, null(), 3, out.as_mut_ptr(), 3, &mut err),
            TRIBEZ_ERROR_NULL
        );
        assert_eq!(take(err).1, "point: NULL pointer");
        assert_eq!(
            tribez_eval_f64_correctly_rounded(
                p,
                [1.0, 0.0, 0.0].as_ptr(),
                3,
                null_mut(),
                3,
                &mut err
            ),
            TRIBEZ_ERROR_NULL
        );
        assert_eq!(take(err).1, "out: NULL pointer");
        tribez_patch_free(p);
    }
}

// --- checks and reports ---------------------------------------------------------------------

/// Rows over Finn's triangle: points `(u, v, 1 - u - v)` and values computed in doubles by a
/// de Casteljau (as examples/c does), with two rows spoiled.
fn rows() -> (Vec<f64>, Vec<f64>) {
    let (mut pts, mut vals) = (Vec::new(), Vec::new());
    for r in 0..300usize {
        let u = (r % 17) as f64 / 17.0;
        let v = (1.0 - u) * ((r / 17) % 19) as f64 / 19.0;
        let w = 1.0 - u - v;
        pts.extend([u, v, w]);
        for c in 0..3 {
            let b = |i: usize| FINN[3 * i + c];
            let b100 = u * b(0) + v * b(1) + w * b(3);
            let b010 = u * b(1) + v * b(2) + w * b(4);
            let b001 = u * b(3) + v * b(4) + w * b(5);
            vals.push(u * b100 + v * b010 + w * b001);
        }
    }
    vals[3 * 100] += 1e-9;
    vals[3 * 250 + 2] *= 1.0 + 1e-15;
    (pts, vals)
}

fn report_strings(r: *const tribez_report) -> (String, String) {
    unsafe {
        (
            taken_string(tribez_report_text(r)),
            taken_string(tribez_report_json(r)),
        )
    }
}

/// The report's text and JSON are byte for byte those of `tribez check --results` on the same
/// rows written as a CSV file (hexadecimal floats: exact), with the names and the numbering
/// (from 1, the file's lines) the command line uses.
#[test]
fn reports_are_byte_identical_to_the_command_lines() {
    let dir = scratch("identical");
    let patch = dir.join("finn.toml");
    std::fs::write(&patch, FINN_TOML).unwrap();
    let (pts, vals) = rows();
    let p = finn();
    for (precision, cartesian, tolerance) in [
        ("f64", false, "ulps=2"),
        ("f64", false, "correctly_rounded"),
        ("f64", true, "cond=9"),
        ("f32", false, "ulps=1"),
        ("f64", false, "bound"),
    ] {
        let (width, points): (usize, Vec<f64>) = if cartesian {
            // reference triangle (1,0), (0,1), (0,0): x = u, y = v
            (2, pts.chunks(3).flat_map(|r| [r[0], r[1]]).collect())
        } else {
            (3, pts.clone())
        };
        let csv = dir.join(format!("rows-{precision}-{cartesian}-{tolerance}.csv"));
        let mut text = String::new();
        for (pt, val) in points.chunks(width).zip(vals.chunks(3)) {
            let row: Vec<String> = pt
                .iter()
                .chain(val)
                .map(|&x| {
                    if precision == "f32" {
                        hex(f64::from(x as f32))
                    } else {
                        hex(x)
                    }
                })
                .collect();
            text += &(row.join(",") + "\n");
        }
        std::fs::write(&csv, text).unwrap();
        let (csv_s, patch_s) = (csv.to_str().unwrap(), patch.to_str().unwrap());
        let o = opts(1, Some(csv_s), Some(patch_s), cartesian);
        let report = if precision == "f32" {
            let (p32, v32): (Vec<f32>, Vec<f32>) = (
                points.iter().map(|&x| x as f32).collect(),
                vals.iter().map(|&x| x as f32).collect(),
            );
            let t = CString::new(tolerance).unwrap();
            let (mut out, mut err) = (null_mut(), null_mut());
            let code = unsafe {
                tribez_check_f32(
                    p,
                    p32.as_ptr(),
                    v32.as_ptr(),
                    300,
                    t.as_ptr(),
                    &o.opts,
                    &mut out,
                    &mut err,
                )
            };
            assert_eq!(code, TRIBEZ_OK);
            out
        } else {
            check64(p, &points, &vals, 300, tolerance, Some(&o.opts)).unwrap()
        };
        let (text, json) = report_strings(report);
        let mut args = vec![
            "check",
            "--patch",
            patch_s,
            "--results",
            csv_s,
            "--precision",
            precision,
            "--tolerance",
            tolerance,
        ];
        if cartesian {
            args.push("--cartesian");
        }
        let out = cli(&args);
        let ok = unsafe { tribez_report_ok(report) };
        assert_eq!(
            out.status.code(),
            Some(if ok { 0 } else { 1 }),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        assert_eq!(
            String::from_utf8(out.stdout).unwrap(),
            text,
            "{tolerance} {precision}"
        );
        args.extend(["--format", "json"]);
        let out = cli(&args);
        assert_eq!(
            String::from_utf8(out.stdout).unwrap(),
            json,
            "{tolerance} {precision}"
        );
        if tolerance == "ulps=2" {
            // the spoiled rows, lines 101 and 251, and nothing else
            assert_eq!(unsafe { tribez_report_failed(report) }, 2);
            assert!(
                text.contains("  line 101: ") && text.contains("  line 251: "),
                "{text}"
            );
        }
        unsafe { tribez_report_free(report) };
    }
    unsafe { tribez_patch_free(p) };
}

#[test]
fn report_accessors() {
    let p = finn();
    let (pts, vals) = rows();
    let r = check64(p, &pts, &vals, 300, "ulps=2", None).unwrap();
    unsafe {
        assert_eq!(tribez_report_checked(r), 300);
        assert_eq!(tribez_report_passed(r), 298);
        assert_eq!(tribez_report_failed(r), 2);
        assert!(!tribez_report_ok(r));
        assert!(tribez_report_fell_back(r) <= 300);
        // row 100's x is off by 1e-9, about 2^-30 / 2^-53 ulps: by far the worst
        let mut worst = 0usize;
        assert!(tribez_report_worst_row(r, &mut worst));
        assert_eq!(worst, 100);
        assert!(tribez_report_max_ulps(r) > 1e6);
        assert!(!tribez_report_worst_row(r, null_mut()));
        let (text, json) = report_strings(r);
        // default names: the rows `<arrays>`, the patch `the patch`
        assert!(text.starts_with("<arrays>: 300 rows checked against the patch (tolerance ulps=2, each number the nearest f64)\n"), "{text}");
        assert!(json.ends_with("}\n") && json.contains("\"results\": \"<arrays>\""));
        // NULL reports
        assert_eq!(tribez_report_checked(null()), 0);
        assert_eq!(tribez_report_passed(null()), 0);
        assert_eq!(tribez_report_failed(null()), 0);
        assert_eq!(tribez_report_fell_back(null()), 0);
        assert!(!tribez_report_ok(null()));
        assert!(tribez_report_max_ulps(null()).is_nan());
        assert!(!tribez_report_worst_row(null(), &mut worst));
        assert!(tribez_report_text(null()).is_null());
        assert!(tribez_report_json(null()).is_null());
        tribez_report_free(r);
        tribez_report_free(null_mut());
        // every row non-finite: no worst row, max_ulps NaN, failed rows not an error
        let r = check64(
            p,
            &[0.5, 0.25, 0.25],
            &[f64::NAN, 0.625, 0.6875],
            1,
            "exact",
            None,
        )
        .unwrap();
        assert_eq!(tribez_report_failed(r), 1);
        assert!(tribez_report_max_ulps(r).is_nan());
        assert!(!tribez_report_worst_row(r, &mut worst));
        tribez_report_free(r);
        // a passing report: the dyadic point's exact values (hand derivation above)
        let r = check64(
            p,
            &[0.5, 0.25, 0.25],
            &[0.375, 0.625, 0.6875],
            1,
            "exact",
            None,
        )
        .unwrap();
        assert!(tribez_report_ok(r));
        assert_eq!(tribez_report_max_ulps(r), 0.0);
        tribez_report_free(r);
        // Cartesian (x, y) = (u, v)
        let o = opts(0, None, None, true);
        let r = check64(
            p,
            &[0.5, 0.25],
            &[0.375, 0.625, 0.6875],
            1,
            "exact",
            Some(&o.opts),
        )
        .unwrap();
        assert!(tribez_report_ok(r));
        tribez_report_free(r);
        tribez_patch_free(p);
    }
}

#[test]
fn check_errors() {
    let p = finn();
    let (pts, vals) = (vec![0.5, 0.25, 0.25], vec![0.375, 0.625, 0.6875]);
    let e = |r: Result<*mut tribez_report, (c_int, String)>| r.unwrap_err();
    assert_eq!(
        e(check64(null(), &pts, &vals, 1, "exact", None)),
        (TRIBEZ_ERROR_NULL, "patch: NULL pointer".into())
    );
    assert!(
        e(check64(p, &pts, &vals, 1, "ulps=-1", None))
            .1
            .starts_with("tolerance: ")
    );
    assert!(
        e(check64(p, &pts, &vals, 1, "nonsense", None))
            .1
            .starts_with("tolerance: ")
    );
    assert!(
        e(check64(p, &pts, &vals, 1, "", None))
            .1
            .starts_with("tolerance: ")
    );
    let (code, msg) = e(check64(p, &pts, &vals, 0, "exact", None));
    assert_eq!(code, TRIBEZ_ERROR_INPUT);
    assert!(
        msg.contains("no result rows") || msg.contains("no rows"),
        "{msg}"
    );
    assert!(
        e(check64(p, &pts, &vals, usize::MAX, "exact", None))
            .1
            .contains("pass the largest size")
    );
    let mut o = opts(0, None, None, false);
    o.opts.algorithm = 7;
    assert!(
        e(check64(p, &pts, &vals, 1, "exact", Some(&o.opts)))
            .1
            .starts_with("algorithm: 7 is not an algorithm")
    );
    let o = opts(usize::MAX, None, None, false);
    let (_, msg) = e(check64(
        p,
        &[pts.clone(), pts.clone()].concat(),
        &[vals.clone(), vals.clone()].concat(),
        2,
        "exact",
        Some(&o.opts),
    ));
    assert!(msg.contains("passes the largest row index"), "{msg}");
    // a rational patch is refused
    let rational = CString::new(format!("{FINN_TOML}[weights]\n\"2,0,0\" = \"1\"\n\"1,1,0\" = \"2\"\n\"0,2,0\" = \"1\"\n\"1,0,1\" = \"1\"\n\"0,1,1\" = \"1\"\n\"0,0,2\" = \"1\"\n")).unwrap();
    let mut err = null_mut();
    let rp = unsafe { tribez_patch_from_text(rational.as_ptr(), c"toml".as_ptr(), &mut err) };
    assert!(!rp.is_null(), "{:?}", (!err.is_null()).then(|| take(err)));
    assert_eq!(
        e(check64(rp, &pts, &vals, 1, "exact", None)).1,
        "patch: check judges polynomial Bézier patches, not rational patches (for those: claim files)"
    );
    // but evaluates: weights (1, 2, 1, 1, 1, 1) at (1, 0, 0) give control point 200
    assert_eq!(eval_exact(rp, &["1", "0", "0"]).unwrap(), ["0", "0", "0"]);
    let (mut out, t) = (null_mut(), c"exact");
    unsafe {
        for (points, values, tol, outp, what) in [
            (
                null(),
                vals.as_ptr(),
                t.as_ptr(),
                &mut out as *mut _,
                "points",
            ),
            (
                pts.as_ptr(),
                null(),
                t.as_ptr(),
                &mut out as *mut _,
                "values",
            ),
            (
                pts.as_ptr(),
                vals.as_ptr(),
                null(),
                &mut out as *mut _,
                "tolerance",
            ),
            (pts.as_ptr(), vals.as_ptr(), t.as_ptr(), null_mut(), "out"),
        ] {
            let mut err = null_mut();
            assert_eq!(
                tribez_check_f64(p, points, values, 1, tol, null(), outp, &mut err),
                TRIBEZ_ERROR_NULL
            );
            assert_eq!(take(err).1, format!("{what}: NULL pointer"));
            let mut err = null_mut();
            let (p32, v32) = (points.cast::<f32>(), values.cast::<f32>());
            assert_eq!(
                tribez_check_f32(p, p32, v32, 1, tol, null(), outp, &mut err),
                TRIBEZ_ERROR_NULL
            );
            assert_eq!(take(err).1, format!("{what}: NULL pointer"));
        }
        // an f32 batch: a value past the largest f32 is a failed row
        let (p32, v32) = ([0.5f32, 0.25, 0.25], [f32::INFINITY, 0.625, 0.6875]);
        let mut out = null_mut();
        assert_eq!(
            tribez_check_f32(
                p,
                p32.as_ptr(),
                v32.as_ptr(),
                1,
                t.as_ptr(),
                null(),
                &mut out,
                null_mut()
            ),
            TRIBEZ_OK
        );
        assert_eq!(tribez_report_failed(out), 1);
        tribez_report_free(out);
        tribez_patch_free(rp);
        tribez_patch_free(p);
    }
}

#[test]
fn merge() {
    let p = finn();
    let (pts, vals) = rows();
    let whole = check64(p, &pts, &vals, 300, "ulps=2", None).unwrap();
    let a = check64(p, &pts[..360], &vals[..360], 120, "ulps=2", None).unwrap();
    let o = opts(120, None, None, false);
    let b = check64(p, &pts[360..], &vals[360..], 180, "ulps=2", Some(&o.opts)).unwrap();
    let other_tol = check64(p, &pts[360..], &vals[360..], 180, "ulps=3", Some(&o.opts)).unwrap();
    let other_patch = {
        let mut net = FINN;
        net[0] = 1.0;
        let q = unsafe { tribez_patch_from_f64(2, 2, 3, net.as_ptr(), null_mut()) };
        let r = check64(q, &pts[360..], &vals[360..], 180, "ulps=2", Some(&o.opts)).unwrap();
        unsafe { tribez_patch_free(q) };
        r
    };
    let mut err = null_mut();
    unsafe {
        assert_eq!(
            tribez_report_merge(a, other_tol, &mut err),
            TRIBEZ_ERROR_INPUT
        );
        assert!(
            take(err)
                .1
                .starts_with("merge: reports judged with different tolerances")
        );
        assert_eq!(
            tribez_report_merge(a, other_patch, &mut err),
            TRIBEZ_ERROR_INPUT
        );
        assert!(
            take(err)
                .1
                .starts_with("merge: reports judged differently (patch ")
        );
        assert_eq!(tribez_report_merge(a, a, &mut err), TRIBEZ_ERROR_INPUT);
        assert!(take(err).1.contains("with itself"));
        assert_eq!(
            tribez_report_merge(null_mut(), b, &mut err),
            TRIBEZ_ERROR_NULL
        );
        assert_eq!(take(err).1, "into: NULL pointer");
        assert_eq!(tribez_report_merge(a, null(), &mut err), TRIBEZ_ERROR_NULL);
        assert_eq!(take(err).1, "other: NULL pointer");
        // nothing changed by the failures
        assert_eq!(tribez_report_checked(a), 120);
        err = null_mut(); // the ones taken above are freed
        assert_eq!(tribez_report_merge(a, b, &mut err), TRIBEZ_OK);
        assert!(err.is_null());
        assert_eq!(report_strings(a), report_strings(whole));
        assert_eq!(tribez_report_merge(a, b, &mut err), TRIBEZ_ERROR_INPUT);
        assert_eq!(
            take(err).1,
            "merge: both reports have row 120: merge reports of disjoint row sets (give each part its first_row)"
        );
        for r in [whole, a, b, other_tol, other_patch] {
            tribez_report_free(r);
        }
        tribez_patch_free(p);
    }
}

// --- errors, panics, threads ----------------------------------------------------------------

#[test]
fn a_panic_inside_is_an_error() {
    for in_worker in [0, 1] {
        let mut err = null_mut();
        let code = unsafe { tribez__panic_for_test(c"on purpose".as_ptr(), in_worker, &mut err) };
        assert_eq!(code, TRIBEZ_ERROR_INTERNAL);
        let (c, msg) = take(err);
        assert_eq!(c, TRIBEZ_ERROR_INTERNAL);
        assert_eq!(
            msg,
            "internal error in tribez (please report it): on purpose"
        );
    }
    // without err: the status alone
    assert_eq!(
        unsafe { tribez__panic_for_test(c"again".as_ptr(), 0, null_mut()) },
        TRIBEZ_ERROR_INTERNAL
    );
    // and the library still works afterwards
    let p = finn();
    assert_eq!(
        eval_exact(p, &["1/2", "1/3", "1/6"]).unwrap(),
        ["4/9", "5/9", "29/36"]
    );
    unsafe { tribez_patch_free(p) };
}

#[test]
fn error_and_string_functions() {
    unsafe {
        assert!(tribez_error_message(null()).is_null());
        assert_eq!(tribez_error_code(null()), TRIBEZ_OK);
        tribez_error_free(null_mut());
        tribez_string_free(null_mut());
        let v = CStr::from_ptr(tribez_version()).to_str().unwrap();
        assert_eq!(v, env!("CARGO_PKG_VERSION"));
    }
}

#[test]
fn threads_share_a_patch_and_use_their_own_reports() {
    struct Shared(*mut tribez_patch);
    // SAFETY: the handle is only read by the threads (the ABI's promise under test)
    unsafe impl Sync for Shared {}
    impl Shared {
        fn get(&self) -> *mut tribez_patch {
            self.0
        }
    }
    let p = Shared(finn());
    let (pts, vals) = rows();
    let counts: Vec<u64> = std::thread::scope(|s| {
        let hs: Vec<_> = (0..4)
            .map(|_| {
                s.spawn(|| {
                    let r = check64(p.get(), &pts, &vals, 300, "ulps=2", None).unwrap();
                    let n = unsafe { tribez_report_passed(r) };
                    let v = eval_exact(p.get(), &["1/2", "1/3", "1/6"]).unwrap();
                    assert_eq!(v, ["4/9", "5/9", "29/36"]);
                    unsafe { tribez_report_free(r) };
                    n
                })
            })
            .collect();
        hs.into_iter().map(|h| h.join().unwrap()).collect()
    });
    assert_eq!(counts, [298; 4]);
    unsafe { tribez_patch_free(p.0) };
}

// --- hunt -----------------------------------------------------------------------------------

/// A target: Finn's triangle by de Casteljau in doubles; with a non-NULL `ctx`, a planted
/// fault (x off by 2^-20 relative where u < 2^-10, a corner region a uniform search rarely hits).
unsafe extern "C" fn finn_target(
    ctx: *mut std::ffi::c_void,
    inputs: *const f64,
    rows: usize,
    outputs: *mut f64,
) {
    let inputs = unsafe { std::slice::from_raw_parts(inputs, rows * 3) };
    let outputs = unsafe { std::slice::from_raw_parts_mut(outputs, rows * 3) };
    for (p, out) in inputs.chunks(3).zip(outputs.chunks_mut(3)) {
        let (u, v, w) = (p[0], p[1], p[2]);
        for c in 0..3 {
            let b = |i: usize| FINN[3 * i + c];
            let b100 = u * b(0) + v * b(1) + w * b(3);
            let b010 = u * b(1) + v * b(2) + w * b(4);
            let b001 = u * b(3) + v * b(4) + w * b(5);
            out[c] = u * b100 + v * b010 + w * b001;
        }
        if !ctx.is_null() && u < 1.0 / 1024.0 {
            out[0] *= 1.0 + 1.0 / 1048576.0;
        }
    }
}

fn hunt_run(
    target: tribez_hunt_target,
    ctx: *mut std::ffi::c_void,
    tol: &str,
    o: Option<&tribez_hunt_options>,
) -> Result<*mut tribez_hunt_report, (c_int, String)> {
    let p = finn();
    let t = CString::new(tol).unwrap();
    let (mut out, mut err) = (null_mut(), null_mut());
    let code = unsafe {
        tribez_hunt(
            p,
            target,
            ctx,
            t.as_ptr(),
            o.map_or(null(), |o| o as *const _),
            &mut out,
            &mut err,
        )
    };
    unsafe { tribez_patch_free(p) };
    if code != TRIBEZ_OK {
        assert!(out.is_null());
        return Err(take(err));
    }
    Ok(out)
}

#[test]
fn hunt_finds_a_planted_fault_and_passes_a_sound_target() {
    let o = tribez_hunt_options {
        budget: 3000,
        seed: 1,
        cartesian: false,
        batch: 0,
        top: 0,
    };
    unsafe {
        let sound = hunt_run(Some(finn_target), null_mut(), "bound", Some(&o)).unwrap();
        assert_eq!(tribez_hunt_report_evaluated(sound), 3000);
        assert_eq!(tribez_hunt_report_broke(sound), 0);
        tribez_hunt_report_free(sound);
        let mut flag = 1u8;
        let ctx = (&mut flag as *mut u8).cast();
        let faulty = hunt_run(Some(finn_target), ctx, "bound", Some(&o)).unwrap();
        assert!(tribez_hunt_report_broke(faulty) > 0);
        assert!((1..=10).contains(&tribez_hunt_report_worst_len(faulty)));
        let (mut input, mut claimed) = ([0.0; 3], [0.0; 3]);
        let ulps = tribez_hunt_report_worst(faulty, 0, input.as_mut_ptr(), claimed.as_mut_ptr());
        // the planted error: 2^-20 relative, about 2^32 ulps of x
        assert!(ulps > 1e6, "{ulps}");
        assert!(input[0] < 1.0 / 1024.0, "{input:?}");
        // the same seed, the same hunt
        let again = hunt_run(Some(finn_target), ctx, "bound", Some(&o)).unwrap();
        let mut input2 = [0.0; 3];
        assert_eq!(
            tribez_hunt_report_worst(again, 0, input2.as_mut_ptr(), null_mut()),
            ulps
        );
        assert_eq!(input2, input);
        assert!(tribez_hunt_report_worst(faulty, 99, null_mut(), null_mut()).is_nan());
        tribez_hunt_report_free(faulty);
        tribez_hunt_report_free(again);
        // NULL reports
        assert_eq!(tribez_hunt_report_evaluated(null()), 0);
        assert_eq!(tribez_hunt_report_broke(null()), 0);
        assert_eq!(tribez_hunt_report_worst_len(null()), 0);
        assert!(tribez_hunt_report_worst(null(), 0, null_mut(), null_mut()).is_nan());
        tribez_hunt_report_free(null_mut());
    }
}

#[test]
fn hunt_errors() {
    assert_eq!(
        hunt_run(None, null_mut(), "bound", None).unwrap_err(),
        (TRIBEZ_ERROR_NULL, "target: NULL pointer".into())
    );
    assert!(
        hunt_run(Some(finn_target), null_mut(), "ulps=", None)
            .unwrap_err()
            .1
            .starts_with("tolerance: ")
    );
    let o = tribez_hunt_options {
        budget: u64::MAX,
        seed: 0,
        cartesian: false,
        batch: 0,
        top: 0,
    };
    assert!(
        hunt_run(Some(finn_target), null_mut(), "bound", Some(&o))
            .unwrap_err()
            .1
            .starts_with("budget ")
    );
    let mut err = null_mut();
    let mut out = null_mut();
    assert_eq!(
        unsafe {
            tribez_hunt(
                null(),
                Some(finn_target),
                null_mut(),
                c"bound".as_ptr(),
                null(),
                &mut out,
                &mut err,
            )
        },
        TRIBEZ_ERROR_NULL
    );
    assert_eq!(take(err).1, "patch: NULL pointer");
}

// --- helpers --------------------------------------------------------------------------------

/// A double in C's hexadecimal notation (exact), as the command line reads it.
fn hex(x: f64) -> String {
    if x == 0.0 {
        return if x.is_sign_negative() {
            "-0x0p+0".into()
        } else {
            "0x0p+0".into()
        };
    }
    let bits = x.to_bits();
    let sign = if x < 0.0 { "-" } else { "" };
    let exp = ((bits >> 52) & 0x7ff) as i32;
    let mant = bits & ((1u64 << 52) - 1);
    if exp == 0 {
        format!("{sign}0x0.{mant:013x}p-1022")
    } else {
        format!("{sign}0x1.{mant:013x}p{:+}", exp - 1023)
    }
}

/// A fresh scratch directory under the target directory.
fn scratch(name: &str) -> PathBuf {
    let dir = target_dir()
        .join("tmp")
        .join(format!("tribez-capi-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// target/debug (or the profile the tests run in): the test binary is in its deps/.
fn target_dir() -> PathBuf {
    let exe = std::env::current_exe().unwrap();
    exe.parent().and_then(Path::parent).unwrap().to_path_buf()
}

/// Run the `tribez` binary (`TRIBEZ_CLI`, else the one beside the tests, built first if
/// missing).
fn cli(args: &[&str]) -> std::process::Output {
    static BUILT: std::sync::Once = std::sync::Once::new();
    let bin = std::env::var_os("TRIBEZ_CLI")
        .map(PathBuf::from)
        .unwrap_or_else(|| target_dir().join("tribez"));
    BUILT.call_once(|| {
        if !bin.exists() {
            let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
            let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
            let status = std::process::Command::new(cargo)
                .args(["build", "-p", "tribez-cli", "--quiet"])
                .current_dir(root)
                .status()
                .expect("cargo build -p tribez-cli");
            assert!(status.success(), "cargo build -p tribez-cli failed");
        }
    });
    assert!(
        bin.exists(),
        "{}: no tribez binary (cargo build -p tribez-cli)",
        bin.display()
    );
    std::process::Command::new(&bin)
        .args(args)
        .output()
        .unwrap()
}
