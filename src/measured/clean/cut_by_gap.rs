//! A piece too short to keep because a time gap ends it after its steer
//! moved: the hole took what the piece after it lacks (the running before
//! the steer moves, its onset, the start of the response), and
//! "dropped: too short" alone hid that. A 100 Hz step with 5 rows missing
//! 0.46 s after the steer moved lost its first 1.47 s so, the piece after
//! the hole starting mid-response. The reason says the gap, what the piece
//! held and how to keep it (fill the hole in the file). Times in s, steer
//! in rad.

use crate::error::{GapAt, PieceRefusal};
use crate::measured::MeasuredRun;

/// The least steer change that is a move, rad (0.01°, a step's least).
const MOVE: f64 = 1.745e-4;

/// The share of the piece's largest steer change at which the steer is
/// said to move (a step's onset, as the metrics' 5 %).
const ONSET: f64 = 0.05;

/// The gap after the samples `t[..hi]` of a run of times `t` (none at its
/// end), its missing samples counted on the run's median interval `dt`.
pub(super) fn gap_after(t: &[f64], hi: usize, dt: f64) -> Option<GapAt> {
    let (from, to) = (*t.get(hi.checked_sub(1)?)?, *t.get(hi)?);
    let missing = match dt > 0.0 {
        true => (((to - from) / dt).round() as usize).saturating_sub(1),
        false => 0,
    };
    Some(GapAt { from, to, missing })
}

/// Why `piece`, shorter than `least` (s), is dropped: cut by the time gap
/// `gap` that ends it where its steer moved, else too short.
pub(super) fn too_short(piece: &MeasuredRun, least: f64, gap: Option<GapAt>) -> PieceRefusal {
    let (Some(gap), Some(&first)) = (gap, piece.steer.first()) else {
        return PieceRefusal::TooShort;
    };
    let change = piece
        .steer
        .iter()
        .map(|d| d - first)
        .filter(|d| d.is_finite())
        .fold(0.0_f64, |m, d| if d.abs() > m.abs() { d } else { m });
    if change.abs() < MOVE {
        return PieceRefusal::TooShort;
    }
    let Some(k) = piece
        .steer
        .iter()
        .position(|d| (d - first).abs() >= ONSET * change.abs())
    else {
        return PieceRefusal::TooShort;
    };
    let (t0, t1) = (piece.t[0], piece.t[piece.t.len() - 1]);
    // Too few samples in a long enough piece: not the gap's doing.
    if t1 - t0 >= least {
        return PieceRefusal::TooShort;
    }
    PieceRefusal::CutByGap {
        length: t1 - t0,
        least,
        before: piece.t[k] - t0,
        moves_at: piece.t[k],
        change,
        gap,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn piece(step_at: f64, to: f64) -> MeasuredRun {
        let t: Vec<f64> = (300..=(to * 100.0).round() as i32)
            .map(|i| f64::from(i) / 100.0)
            .collect();
        let steer = t
            .iter()
            .map(|t| if *t >= step_at { 0.02 } else { 0.0 })
            .collect();
        let n = t.len();
        MeasuredRun::new("p.csv", t, vec![20.0; n], steer, vec![0.0; n])
    }

    #[test]
    fn a_short_piece_whose_steer_moves_before_a_gap_is_cut_by_it() {
        let t: Vec<f64> = (0..600)
            .map(|i| f64::from(i) / 100.0)
            .filter(|t| !(4.475..4.525).contains(t))
            .collect();
        let hi = t.partition_point(|x| *x <= 4.47);
        let gap = gap_after(&t, hi, 0.01).unwrap();
        assert_eq!(gap.missing, 5, "{gap}");
        let why = too_short(&piece(4.01, 4.47), 2.0, Some(gap));
        let PieceRefusal::CutByGap {
            before, moves_at, ..
        } = why
        else {
            panic!("{why}");
        };
        assert!((before - 1.01).abs() < 1e-9 && (moves_at - 4.01).abs() < 1e-9);
        let said = why.to_string();
        assert!(
            said.contains("the first 0.46 s of the response")
                && said.contains("fill the hole in the file"),
            "{said}"
        );
        // A held steer, or no gap: too short, as before.
        assert_eq!(
            too_short(&piece(9.0, 4.47), 2.0, Some(gap)),
            PieceRefusal::TooShort
        );
        assert_eq!(
            too_short(&piece(4.01, 4.47), 2.0, None),
            PieceRefusal::TooShort
        );
        assert_eq!(gap_after(&t, t.len(), 0.01), None);
    }
}
