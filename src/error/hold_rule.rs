//! A value given with `identify --hold` that the model's own sign rules
//! refuse: a held value is not fitted, so a wrong sign (`PKY1 = 50` for
//! ISO-W's −50) cannot be undone by the fit, and the other parameters
//! bend to make up for it (σ 29.6 % on the Hoosier file, then a `PCY1`
//! the readers refuse). The rules are those the fit's bounds encode
//! (Pacejka 2012, ISO 8855 / ISO-W signs: a tyre's lateral force pushes
//! against its slip angle, a driven wheel's longitudinal force along its
//! slip ratio). Values in the tyre file's units.

use super::number::Num;
use std::fmt;

/// Which sign rule a held value breaks.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum HoldRule {
    /// The fit keeps the parameter in a box of one sign, `(lo, hi)`, and
    /// the value has the other (or is zero where the box excludes it).
    OneSigned {
        /// The box's lower end.
        lo: f64,
        /// The box's upper end.
        hi: f64,
        /// What the parameter is, where known ("the shape factor C").
        what: Option<&'static str>,
    },
    /// `PKY1` of the sign that makes the cornering stiffness
    /// `Kyα = PKY1·FNOMIN·sin(PKY4·atan(Fz/(PKY2·FNOMIN)))·LKY` positive
    /// at light loads: `pky4` the value held for `PKY4`, or `None` where
    /// the fit keeps it positive (0.1 to 5).
    CorneringStiffness {
        /// `PKY4` as held, if it was.
        pky4: Option<f64>,
    },
    /// A negative `PKX1`: the slip stiffness at `FNOMIN`,
    /// `Kxκ = PKX1·FNOMIN·LKX`, is positive in ISO-W.
    SlipStiffness,
}

/// A held value refused by a [`HoldRule`], named as the command line gave it.
#[derive(Debug, Clone, PartialEq)]
pub struct HoldAgainstRule {
    /// The parameter, as the tyre file names it.
    pub name: String,
    /// The value given.
    pub value: f64,
    /// The rule it breaks.
    pub rule: HoldRule,
}

impl fmt::Display for HoldAgainstRule {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let (name, v) = (&self.name, self.value);
        write!(f, "--hold {name}={}: ", Num(v))?;
        match self.rule {
            HoldRule::OneSigned { lo, hi, what } => {
                let what = what.map_or_else(String::new, |w| format!(" ({w})"));
                let sign = if lo >= 0.0 { "positive" } else { "negative" };
                write!(
                    f,
                    "{name}{what} is {sign} in every tyre the fit makes (it keeps {name} within {} to {}, ISO-W signs as the tyre file has them); a held value is not fitted, so the other parameters would bend to make up for it",
                    Num(lo),
                    Num(hi)
                )?;
                if (lo..=hi).contains(&-v) {
                    write!(f, ": did you mean {}?", Num(-v))?;
                }
                Ok(())
            }
            HoldRule::CorneringStiffness { pky4 } => {
                let why = match pky4 {
                    Some(k) => format!("with PKY4 held at {}, PKY1 must be {}", Num(k), if k < 0.0 { "positive" } else { "negative" }),
                    None => "the fit keeps PKY4 within 0.1 to 5 and PKY2 positive, so PKY1 must be negative".into(),
                };
                write!(
                    f,
                    "the lateral stiffness factor has the wrong sign: in ISO-W a tyre's lateral force pushes against its slip angle, so the cornering stiffness Kyα = PKY1·FNOMIN·sin(PKY4·atan(Fz/(PKY2·FNOMIN)))·LKY is negative; {why}: did you mean {}?",
                    Num(-v)
                )
            }
            HoldRule::SlipStiffness => write!(
                f,
                "the longitudinal slip stiffness Kxκ = FNOMIN·(PKX1 + PKX2·dfz)·exp(PKX3·dfz)·LKX is positive in ISO-W (a positive slip ratio drives the wheel forward), PKX1·FNOMIN·LKX at FNOMIN, so PKX1 must be positive: did you mean {}?",
                Num(-v)
            ),
        }
    }
}
