//! Small dense linear algebra for fits with a handful of unknowns (calibration, the loop's
//! linear effects, the pyranometer closure): Gaussian elimination, linear least squares through
//! column-scaled normal equations (with or without dropping collinear columns), non-negative
//! least squares by enumerating active sets, and a symmetric solve for Levenberg-Marquardt steps.

/// Solves `a x = b` for a square `a` (row-major, n x n) by Gaussian elimination with partial
/// pivoting. `None` when `a` is singular to working precision.
pub fn solve(a: &[Vec<f64>], b: &[f64]) -> Option<Vec<f64>> {
    let n = b.len();
    let mut m: Vec<Vec<f64>> = a
        .iter()
        .zip(b)
        .map(|(row, &v)| {
            let mut r = row.clone();
            r.push(v);
            r
        })
        .collect();
    let scale = m
        .iter()
        .flat_map(|r| r[..n].iter())
        .fold(0.0f64, |s, v| s.max(v.abs()));
    if !(scale > 0.0 && scale.is_finite()) {
        return None;
    }
    for col in 0..n {
        let pivot = (col..n).max_by(|&i, &j| m[i][col].abs().total_cmp(&m[j][col].abs()))?;
        if m[pivot][col].abs() <= scale * 1e-14 {
            return None;
        }
        m.swap(col, pivot);
        let (top, bottom) = m.split_at_mut(col + 1);
        let pivot_row = &top[col];
        for r in bottom.iter_mut() {
            let f = r[col] / pivot_row[col];
            if f != 0.0 {
                for (x, p) in r[col..].iter_mut().zip(&pivot_row[col..]) {
                    *x -= f * p;
                }
            }
        }
    }
    let mut x = vec![0.0; n];
    for row in (0..n).rev() {
        let s: f64 = (row + 1..n).map(|k| m[row][k] * x[k]).sum();
        x[row] = (m[row][n] - s) / m[row][row];
    }
    x.iter().all(|v| v.is_finite()).then_some(x)
}

/// `AᵀA` and `Aᵀy` for a design matrix given as rows.
pub fn normal_equations(rows: &[Vec<f64>], y: &[f64]) -> (Vec<Vec<f64>>, Vec<f64>) {
    let n = rows.first().map_or(0, Vec::len);
    let mut ata = vec![vec![0.0; n]; n];
    let mut aty = vec![0.0; n];
    for (row, &v) in rows.iter().zip(y) {
        for i in 0..n {
            aty[i] += row[i] * v;
            for j in 0..n {
                ata[i][j] += row[i] * row[j];
            }
        }
    }
    (ata, aty)
}

/// Least squares `min |A x - y|²` through the normal equations with columns scaled to unit
/// diagonal (so columns of different magnitude stay comparable). `None` when rank deficient.
pub fn least_squares(rows: &[Vec<f64>], y: &[f64]) -> Option<Vec<f64>> {
    let (ata, aty) = normal_equations(rows, y);
    solve_scaled(&ata, &aty)
}

/// Solves a symmetric positive (semi-)definite system with its diagonal scaled to 1 first.
pub fn solve_scaled(a: &[Vec<f64>], b: &[f64]) -> Option<Vec<f64>> {
    let n = b.len();
    let d: Vec<f64> = (0..n)
        .map(|i| {
            let v = a[i][i];
            if v > 0.0 {
                1.0 / v.sqrt()
            } else {
                1.0
            }
        })
        .collect();
    let scaled: Vec<Vec<f64>> = (0..n)
        .map(|i| (0..n).map(|j| a[i][j] * d[i] * d[j]).collect())
        .collect();
    let sb: Vec<f64> = (0..n).map(|i| b[i] * d[i]).collect();
    let x = solve(&scaled, &sb)?;
    Some((0..n).map(|i| x[i] * d[i]).collect())
}

/// The inverse of a symmetric matrix (for covariances), column by column.
pub fn inverse_scaled(a: &[Vec<f64>]) -> Option<Vec<Vec<f64>>> {
    let n = a.len();
    let mut inv = vec![vec![0.0; n]; n];
    for j in 0..n {
        let mut e = vec![0.0; n];
        e[j] = 1.0;
        let col = solve_scaled(a, &e)?;
        for i in 0..n {
            inv[i][j] = col[i];
        }
    }
    Some(inv)
}

/// Non-negative least squares `min |A x - y|²` subject to `x >= 0`, exact for the few
/// unknowns of a calibration (at most 12): every set of free variables is solved without
/// constraints, and the best feasible solution wins (the optimum is the unconstrained
/// optimum on its own support, so it is among them).
pub fn nnls(rows: &[Vec<f64>], y: &[f64]) -> Option<Vec<f64>> {
    let n = rows.first().map_or(0, Vec::len);
    if n == 0 || n > 12 {
        return None;
    }
    let cost = |x: &[f64]| -> f64 {
        rows.iter()
            .zip(y)
            .map(|(r, v)| {
                let p: f64 = r.iter().zip(x).map(|(a, b)| a * b).sum();
                (p - v).powi(2)
            })
            .sum()
    };
    let mut best = (cost(&vec![0.0; n]), vec![0.0; n]);
    for mask in 1u32..(1 << n) {
        let free: Vec<usize> = (0..n).filter(|i| mask & (1 << i) != 0).collect();
        let sub: Vec<Vec<f64>> = rows
            .iter()
            .map(|r| free.iter().map(|&i| r[i]).collect())
            .collect();
        let Some(xs) = least_squares(&sub, y) else {
            continue;
        };
        if xs.iter().any(|v| *v < 0.0) {
            continue;
        }
        let mut x = vec![0.0; n];
        for (&i, v) in free.iter().zip(xs) {
            x[i] = v;
        }
        let c = cost(&x);
        if c < best.0 {
            best = (c, x);
        }
    }
    Some(best.1)
}

/// A column whose part outside the span of the columns before it has less than this share of
/// its squared norm (1 %² of its norm) cannot be told apart from them on these samples.
const COLLINEAR_SHARE: f64 = 1e-4;

/// Least squares through the normal equations, columns scaled to unit norm, eliminated in
/// order without pivoting (the matrix is positive semi-definite). A column (nearly) in the span
/// of the columns before it is dropped: its coefficient is 0 and its flag is set. `None` only
/// for non-finite input.
pub fn least_squares_dropping_collinear(
    rows: &[Vec<f64>],
    y: &[f64],
) -> Option<(Vec<f64>, Vec<bool>)> {
    let k = rows.first().map_or(0, Vec::len);
    let mut a = vec![vec![0.0; k + 1]; k];
    for (row, &yi) in rows.iter().zip(y) {
        for i in 0..k {
            for j in 0..k {
                a[i][j] += row[i] * row[j];
            }
            a[i][k] += row[i] * yi;
        }
    }
    if a.iter().flatten().any(|v| !v.is_finite()) {
        return None;
    }
    let scale: Vec<f64> = (0..k).map(|i| a[i][i].sqrt()).collect();
    let mut dropped: Vec<bool> = scale.iter().map(|s| s.is_nan() || *s <= 0.0).collect();
    for i in 0..k {
        for j in 0..k {
            if !(dropped[i] || dropped[j]) {
                a[i][j] /= scale[i] * scale[j];
            }
        }
        if !dropped[i] {
            a[i][k] /= scale[i];
        }
    }
    // Gauss-Jordan in column order: the pivot a[c][c] is then the squared norm share of
    // column c outside the span of the kept columns before it.
    for c in 0..k {
        if dropped[c] || a[c][c] < COLLINEAR_SHARE {
            dropped[c] = true;
            for row in a.iter_mut() {
                row[c] = 0.0;
            }
            a[c].iter_mut().for_each(|v| *v = 0.0);
            a[c][c] = 1.0;
            a[c][k] = 0.0;
            continue;
        }
        let pivot_row = a[c].clone();
        for (i, row) in a.iter_mut().enumerate() {
            if i != c {
                let f = row[c] / pivot_row[c];
                for (v, p) in row.iter_mut().zip(&pivot_row).skip(c) {
                    *v -= f * p;
                }
            }
        }
    }
    let x: Vec<f64> = (0..k)
        .map(|i| {
            if dropped[i] {
                0.0
            } else {
                a[i][k] / a[i][i] / scale[i]
            }
        })
        .collect();
    x.iter().all(|v| v.is_finite()).then_some((x, dropped))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn solves_and_fits() {
        let a = vec![vec![2.0, 1.0], vec![1.0, 3.0]];
        let x = solve(&a, &[3.0, 5.0]).unwrap();
        assert!((x[0] - 0.8).abs() < 1e-12 && (x[1] - 1.4).abs() < 1e-12);
        assert!(solve(&[vec![1.0, 2.0], vec![2.0, 4.0]], &[1.0, 2.0]).is_none());
        // y = 1 + 2 x exactly.
        let rows: Vec<Vec<f64>> = (0..5).map(|i| vec![1.0, i as f64]).collect();
        let y: Vec<f64> = (0..5).map(|i| 1.0 + 2.0 * i as f64).collect();
        let c = least_squares(&rows, &y).unwrap();
        assert!((c[0] - 1.0).abs() < 1e-10 && (c[1] - 2.0).abs() < 1e-10);
    }

    #[test]
    fn nnls_clamps_a_negative_coefficient() {
        // y = 1 x0 - 0.5 x1 without constraint; with x >= 0 the second is 0.
        let rows: Vec<Vec<f64>> = (0..10)
            .map(|i| vec![1.0 + i as f64, (i as f64 * 0.7).sin() + 2.0])
            .collect();
        let y: Vec<f64> = rows.iter().map(|r| r[0] - 0.5 * r[1]).collect();
        let x = nnls(&rows, &y).unwrap();
        assert_eq!(x[1], 0.0);
        assert!(x[0] > 0.0);
        let unconstrained = least_squares(&rows, &y).unwrap();
        assert!((unconstrained[1] + 0.5).abs() < 1e-9);
    }
}
