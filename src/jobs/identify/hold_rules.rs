//! The sign rules and boxes a value given with `--hold` is checked
//! against before any data are read. A held value is not fitted: a wrong
//! sign (`PKY1 = 50` where ISO-W's Magic Formula has −50) cannot be undone
//! by the fit, which bends every other parameter to make up for it (σ 29.6 %
//! on the Hoosier file and a `PCY1` the readers then refuse). Refused: a
//! value of the other sign than the fit's box for it (ISO-W signs, as the
//! tyre file has them), a `PKY1` whose cornering stiffness
//! `Kyα = PKY1·FNOMIN·sin(PKY4·atan(Fz/(PKY2·FNOMIN)))·LKY` would be
//! positive at light loads, and a negative `PKX1` (`Kxκ = PKX1·FNOMIN·LKX`
//! at `FNOMIN`, positive) (Pacejka 2012, §4.3). Warned: a value of the
//! right sign outside the box the fit would search. Units: the tyre
//! file's.

use super::{IdentifyModel, Options};
use crate::error::{Error, HoldAgainstRule, HoldRule, OptionsError};
use crate::tyre::ModelName;

/// The fit's box of `name`: the staged Magic Formula's fixed physical
/// bounds (`model` `None`), or a swarm model's search box.
fn box_of(model: Option<ModelName>, name: &str) -> Option<(f64, f64)> {
    match model {
        None => crate::identify::mf_staged::fixed_bounds(name),
        Some(m) => {
            let start = super::start_tyre_of(m, super::holds::CHECK_LOAD).ok()?;
            crate::identify::bounds_in(&start, name)
        }
    }
}

/// What a staged Magic Formula coefficient with a one-signed box is.
fn what(name: &str) -> Option<&'static str> {
    match name {
        "PCX1" | "PCY1" => Some("the shape factor C of a pure force, at least 1"),
        "RCX1" | "RCY1" | "QCZ1" => Some("a shape factor"),
        "PDX1" | "PDY1" => Some("the peak friction at FNOMIN"),
        "PKY2" => Some("the load of the cornering stiffness's peak, over FNOMIN"),
        "QBZ1" | "RBX1" | "RBY1" => Some("a stiffness factor"),
        _ => None,
    }
}

/// Whether `v` has the other sign than every value of `(lo, hi)` (or is
/// zero where the box lies strictly on one side of it).
fn against_box(v: f64, (lo, hi): (f64, f64)) -> bool {
    (lo >= 0.0 && (v < 0.0 || (v == 0.0 && lo > 0.0)))
        || (hi <= 0.0 && (v > 0.0 || (v == 0.0 && hi < 0.0)))
}

/// Refuses a held value against a sign rule of `model` (`None`: the
/// staged Magic Formula), with the rule and the value meant.
pub(crate) fn check_signs(model: Option<ModelName>, hold: &[(String, f64)]) -> Result<(), Error> {
    let refuse = |name: &str, value: f64, rule| {
        Err(OptionsError::HoldAgainstRule(Box::new(HoldAgainstRule {
            name: name.into(),
            value,
            rule,
        }))
        .into())
    };
    let given = |n: &str| hold.iter().find(|(k, _)| k == n).map(|(_, v)| *v);
    for (name, v) in hold {
        let v = *v;
        if model.is_none() {
            match name.as_str() {
                // MFeval's files write PKY1 > 0 with PKY4 < 0: the product
                // is what has a sign, and PKY4's box holds only for a fit.
                "PKY4" => continue,
                "PKY1" => {
                    let pky4 = given("PKY4");
                    if v != 0.0 && v * pky4.unwrap_or(1.0) > 0.0 {
                        return refuse(name, v, HoldRule::CorneringStiffness { pky4 });
                    }
                    continue;
                }
                "PKX1" if v < 0.0 => return refuse(name, v, HoldRule::SlipStiffness),
                _ => {}
            }
        }
        if let Some((lo, hi)) = box_of(model, name).filter(|b| against_box(v, *b)) {
            let what = model.is_none().then(|| what(name)).flatten();
            return refuse(name, v, HoldRule::OneSigned { lo, hi, what });
        }
    }
    Ok(())
}

/// The warnings on held values of the right sign outside the box the fit
/// would have searched: the fit would not have gone there.
pub(crate) fn beyond_box(o: &Options) -> Vec<String> {
    let model = match o.model {
        IdentifyModel::Swarm(m) => Some(m),
        IdentifyModel::Staged(..) => None,
    };
    o.hold
        .iter()
        .filter(|(n, _)| !(model.is_none() && n == "PKY4"))
        .filter_map(|(name, v)| {
            let (lo, hi) = box_of(model, name)?;
            (!(lo..=hi).contains(v)).then(|| {
                format!(
                    "--hold {name}={}: outside the box the fit searches for it, {} to {}: a fit would not have gone there; check the value and its units",
                    crate::error::Num(*v),
                    crate::error::Num(lo),
                    crate::error::Num(hi)
                )
            })
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn refused(model: Option<ModelName>, hold: &[(&str, f64)]) -> Option<String> {
        let hold: Vec<(String, f64)> = hold.iter().map(|(k, v)| (k.to_string(), *v)).collect();
        check_signs(model, &hold).err().map(|e| e.to_string())
    }

    /// PKY1's sign against PKY4's: negative with PKY4 fitted (kept
    /// positive), positive with PKY4 held negative (MFeval's convention).
    #[test]
    fn pky1_is_refused_where_its_cornering_stiffness_turns_positive() {
        let e = refused(None, &[("PKY1", 50.0)]).expect("PKY1 = 50 refused");
        assert!(
            e.starts_with("--hold PKY1=50: ") && e.ends_with("did you mean -50?"),
            "{e}"
        );
        assert_eq!(refused(None, &[("PKY1", -50.0)]), None);
        assert_eq!(refused(None, &[("PKY1", 50.0), ("PKY4", -2.0)]), None);
        assert!(refused(None, &[("PKY4", -2.0), ("PKY1", -50.0)]).is_some());
        assert_eq!(refused(None, &[("PKY4", -2.0)]), None);
    }

    /// A one-signed box refuses the other sign and zero where it
    /// excludes it; PKX1 below zero is refused.
    #[test]
    fn one_signed_boxes_refuse_the_other_sign() {
        assert!(refused(None, &[("PDY1", -1.2)]).is_some_and(|e| e.ends_with("did you mean 1.2?")));
        assert!(refused(None, &[("PCY1", 0.0)]).is_some());
        assert!(refused(None, &[("PKX1", -20.0)]).is_some());
        assert_eq!(refused(None, &[("PEY1", 0.5)]), None);
        assert_eq!(refused(None, &[("QBZ1", 0.0)]), None);
        assert!(refused(Some(ModelName::Pac89), &[("a3", -1000.0)]).is_some());
        assert_eq!(refused(Some(ModelName::Pac89), &[("a1", -500.0)]), None);
    }

    #[test]
    fn against_box_sees_both_sides() {
        assert!(against_box(-1.0, (0.0, 5.0)) && !against_box(0.0, (0.0, 5.0)));
        assert!(against_box(1.0, (-5.0, -1.0)) && against_box(0.0, (-5.0, -1.0)));
        assert!(!against_box(-9.0, (-1.0, 1.0)));
    }
}
