//! The stepping pattern of a ray's path (a column while the error is negative, else a row;
//! `raster_walk.rs`) taken many steps at once: how far it goes within a free square.

use super::divisor::Divisor;

/// The divisors of [`free_steps`] for a ray of `columns` and `rows`: twice each, for the
/// dividends it takes (below `2 (m + 2)²`, `m` the larger of the ray's steps and a free
/// square's 255 cells: a jump moves no farther than either).
pub(super) fn divisors(columns: i64, rows: i64) -> (Divisor, Divisor) {
    let m = columns.saturating_add(rows).max(256);
    let most = if m < 1 << 15 {
        2 * (m + 2) * (m + 2)
    } else {
        i64::MAX
    };
    (
        Divisor::new(columns.saturating_mul(2), most),
        Divisor::new(rows.saturating_mul(2), most),
    )
}

/// The longest start of the stepping pattern from error `error` (a column while it is
/// negative, else a row; a column adds `2 * rows`, a row takes `2 * columns`) that moves at
/// most `most_x` columns and `most_y` rows: how many of each it moves. `by` divides by twice
/// the columns and twice the rows ([`divisors`]).
#[inline(always)]
pub(super) fn free_steps(
    error: i64,
    (columns, rows): (i64, i64),
    by: (Divisor, Divisor),
    most_x: i64,
    most_y: i64,
) -> (i64, i64) {
    if columns == 0 {
        // The error never falls below 0: rows only.
        return (0, most_y);
    }
    // Column `i` (≥ 1) is reached while no more than `most_y` rows have been moved:
    // error + 2 * rows * (i - 1) < 2 * columns * most_y. The largest such i is
    // ceil(room / (2 * rows)), none when there is no room (the dividend is then below one
    // divisor); any with no rows at all.
    let room = 2 * columns * most_y - error;
    let i = if rows == 0 {
        if room > 0 { most_x } else { 0 }
    } else {
        by.1.floor_of((room + 2 * rows - 1).max(0)).min(most_x)
    };
    // Short of `most_x`, column i + 1 comes only after a row past `most_y`: the rows run out
    // first, all of them moved. Else the rows moved before the column after the i-th: until
    // the error falls below 0. Both worked out, one kept, without a branch on which: which
    // way a jump ends follows no pattern a predictor learns.
    let e = error + 2 * rows * i;
    let before = by.0.floor_of(e.max(0)) + 1;
    let before = if e < 0 { 0 } else { before };
    let j = if i < most_x {
        most_y
    } else {
        before.min(most_y)
    };
    (i, j)
}
