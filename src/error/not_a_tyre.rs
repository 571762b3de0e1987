//! A scenario's or campaign's tyre key (`[tyres] front`, `rear`, `file`)
//! naming a file of another kind: rig data most often, which a tyre is
//! fitted from (`handling identify`) before it is given there. Said at the
//! key in place of the TOML reader's "expected `.`, `=`" at the CSV's
//! header.

/// The refusal of `key` = `written`, a file that is rig data (`rig`) or
/// else `what` (a noun phrase), read by `reader`, in a scenario or a
/// `campaign`.
pub(super) fn said(
    key: &str,
    written: &str,
    (rig, what, reader): (bool, &str, &str),
    campaign: bool,
) -> String {
    let tyre = "a tyre file (a Magic Formula .tir, or a TOML tyre with `model = \"…\"` that `handling identify` writes)";
    let what = match rig {
        true => {
            let rig = match campaign {
                true => format!("; or give the rig data itself as `[tyres] rig = \"{written}\"` (with `model`), which the diagnosis fits a tyre to"),
                false => String::new(),
            };
            format!("this is a tyre rig file (a CSV with `fz` and `alpha` or `kappa`), not {tyre}: `handling identify {written} --model pac89` fits a tyre from it, then give the written tyre here{rig}")
        }
        false => format!("this is {what}, not {tyre}: {reader}"),
    };
    format!("`{key}` = \"{written}\": {what}")
}
