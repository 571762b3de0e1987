//! The texts of the refusals of some input slips a fresh user met: a `.tir`
//! cornering stiffness per unit load beyond any tyre's
//! ([`ParamReason::TirCorneringPerLoad`]), a `.tir` pressure read without a
//! `[UNITS] PRESSURE` line ([`ParamReason::TirPressureNoLine`]), and the
//! vehicle's centre of gravity too low for its track
//! ([`ParamReason::CgTooLow`]) or mass a digit off
//! ([`ParamReason::MassDigit`]), or its wheelbase not a + b
//! ([`ParamReason::WheelbaseMismatch`]); each with the values it is built
//! from. Numbers are printed with a few significant digits
//! ([`crate::format::rounded`]: no number with hundreds of digits).

use super::ParamReason;
use crate::format::rounded;

/// Range of the dynamic index `k²/(a·b) = Iz/(m·a·b)`: road cars lie at
/// about 0.8–1.2 (Milliken & Milliken 1995), a racing car with its masses
/// near the centre at 0.6 (the Putnam log's Dallara, 0.59), a long bus or
/// a car with a heavy overhang at about 1.5. The bounds leave room beyond
/// both: 0.4 is a radius of gyration of 0.63·√(a·b), every mass within
/// two thirds of the axles' reach; 2.5 is 1.6·√(a·b), masses beyond the
/// bumpers. Outside them the inertia is a slip: a digit (10× too large
/// reads 8–12), or a unit (g, kg·cm², slug).
pub const DYNAMIC_INDEX: (f64, f64) = (0.4, 2.5);

/// What [`ParamReason::TirCorneringPerLoad`] says, boxed.
#[derive(Debug, Clone, PartialEq)]
pub struct TirPerLoad {
    /// |Kyα| at FNOMIN, N/rad.
    pub stiffness: f64,
    /// FNOMIN, N.
    pub load: f64,
    /// |Kyα|/FNOMIN, 1/rad.
    pub per_load: f64,
    /// The range of any tyre, 1/rad.
    pub range: (f64, f64),
    /// The `PKY1` a slip's undoing gives, its stiffness per unit load, and
    /// whether the slip is a stiffness per degree (else a digit).
    pub hint: Option<(f64, f64, bool)>,
}

/// What [`ParamReason::WheelbaseMismatch`] says, boxed.
#[derive(Debug, Clone, PartialEq)]
pub struct Wheelbase {
    /// Centre of gravity to front axle, m.
    pub a: f64,
    /// Centre of gravity to rear axle, m.
    pub b: f64,
    /// The wheelbase as given, m.
    pub wheelbase: f64,
    /// Where the file reader found `a` and `b` (`` `vehicle.a` at
    /// path:line:column``); empty where not read from a file.
    pub places: Vec<String>,
}

impl ParamReason {
    /// The other keys of the same table the reason compares the value
    /// with: a file's reader says where each is ([`Self::placed`]).
    pub fn read_with(&self) -> &'static [&'static str] {
        match self {
            ParamReason::WheelbaseMismatch(_) => &["a", "b"],
            _ => &[],
        }
    }

    /// The reason with the places of its [`Self::read_with`] keys, as a
    /// file's reader found them.
    pub fn placed(mut self, places: Vec<String>) -> Self {
        if let ParamReason::WheelbaseMismatch(w) = &mut self {
            w.places = places;
        }
        self
    }

    /// [`ParamReason::TirCorneringPerLoad`]: the `stiffness` (N/rad) at
    /// `load` (N), `per_load` of it, outside `range`, and the `hint`.
    pub(crate) fn tir_cornering_per_load(
        (stiffness, load, per_load): (f64, f64, f64),
        range: (f64, f64),
        hint: Option<(f64, f64, bool)>,
    ) -> Self {
        ParamReason::TirCorneringPerLoad(Box::new(TirPerLoad {
            stiffness,
            load,
            per_load,
            range,
            hint,
        }))
    }
}

/// The message of [`ParamReason::TirCorneringPerLoad`].
pub(super) fn tir_per_load(p: &TirPerLoad) -> String {
    let (lo, hi) = p.range;
    let side = match p.per_load > hi {
        true => format!("above any tyre's {}", rounded(hi, 3)),
        false => format!("below any tyre's {}", rounded(lo, 3)),
    };
    let head = format!(
        "gives the tyre a cornering stiffness at FNOMIN = {} N (zero camber, nominal pressure; from PKY1, PKY2, PKY4, LKY) of |Kyα| = {} N/rad, {} N/rad per N of load (Kyα/Fz), {side} (the published .tir files: 6.7–44 at their FNOMIN, a car tyre's about 10–25, Pacejka's book tyre's 12.0 at 4 kN)",
        rounded(p.load, 6),
        rounded(p.stiffness, 4),
        rounded(p.per_load, 3),
    );
    match p.hint {
        Some((pky1, per_load, false)) => format!(
            "{head}: is a digit slipped? PKY1 = {} would give {} N/rad per N",
            rounded(pky1, 5),
            rounded(per_load, 3)
        ),
        Some((pky1, per_load, true)) => format!(
            "{head}: is it a stiffness per degree? PKY1 = {} (57.3 times it) would give {} N/rad per N",
            rounded(pky1, 5),
            rounded(per_load, 3)
        ),
        None => format!("{head}: check PKY1, PKY2 and PKY4"),
    }
}

/// What [`ParamReason::TirPressureNoLine`] says, boxed: a `.tir` file's
/// pressure at `key` read in `FORCE/LENGTH²` (the units' names, `pa` Pa
/// each) for want of a `[UNITS] PRESSURE` line, outside any tyre's with no
/// other unit it is likely in.
#[derive(Debug, Clone, PartialEq)]
pub struct NoPressureLine {
    /// The key (`NOMPRES`, `INFLPRES`).
    pub key: &'static str,
    /// The force and length units' names.
    pub units: (&'static str, &'static str),
    /// That unit in Pa.
    pub pa: f64,
    /// The range of any tyre's, Pa, `(lo, hi]`.
    pub range: (f64, f64),
}

/// The message of [`ParamReason::TirPressureNoLine`]: the unit the
/// pressure is read in, and that the `PRESSURE` line is missing.
pub(super) fn pressure_no_line(p: &NoPressureLine) -> String {
    let (force, length) = p.units;
    let each = match p.pa == 1.0 {
        true => "Pa".to_string(),
        false => format!("{} Pa each", rounded(p.pa, 4)),
    };
    format!(
        "must {}: a tyre's inflation pressure is 10 kPa to 2 MPa (a kart's about 60 kPa, a car's 200–300 kPa, a track bicycle's up to 1.4 MPa); the file's [UNITS] has no PRESSURE line, so {} is read in FORCE/LENGTH², {force}/{length}² ({each}): check the value, or add the PRESSURE line of the unit it is written in (PRESSURE = 'pascal', 'kpa', 'bar', 'psi')",
        crate::error::range(p.range.0, p.range.1),
        p.key
    )
}

/// What [`ParamReason::MassDigit`] says, boxed: a mass a digit off,
/// which the dynamic index and the mass per footprint both say.
#[derive(Debug, Clone, PartialEq)]
pub struct MassDigit {
    /// The mass given, kg.
    pub mass: f64,
    /// The mass with the digit undone, kg.
    pub likely: f64,
    /// The yaw inertia given, kg·m².
    pub yaw_inertia: f64,
    /// a·b, m².
    pub ab: f64,
    /// The wheelbase a + b and the mean track, m.
    pub footprint: (f64, f64),
    /// The range of a vehicle's mass per m² of footprint.
    pub per_area: (f64, f64),
    /// The range of the dynamic index.
    pub index: (f64, f64),
}

/// The message of [`ParamReason::MassDigit`].
pub(super) fn mass_digit(m: &MassDigit) -> String {
    let (l, t) = m.footprint;
    let area = l * t;
    let index = |mass: f64| m.yaw_inertia / (mass * m.ab);
    format!(
        "is {} kg per m² of footprint (a + b = {} m by a mean track of {} m), outside any vehicle's {}–{} (a kart or racing car about 60–160, a car 250–600, a bus or truck 1000–1800), and with yaw_inertia = {} kg·m² a dynamic index yaw_inertia/(mass·a·b) of {}, outside {}–{}: both say a slipped digit in the mass: {} kg would give {} kg/m² and an index of {} (if the mass is right, yaw_inertia is what is {} times off)",
        rounded(m.mass / area, 3),
        rounded(l, 4),
        rounded(t, 4),
        m.per_area.0,
        m.per_area.1,
        rounded(m.yaw_inertia, 6),
        rounded(index(m.mass), 3),
        m.index.0,
        m.index.1,
        rounded(m.likely, 6),
        rounded(m.likely / area, 3),
        rounded(index(m.likely), 3),
        rounded(m.likely.max(m.mass) / m.likely.min(m.mass), 2),
    )
}

/// What [`ParamReason::CgTooLow`] says, boxed.
#[derive(Debug, Clone, PartialEq)]
pub struct CgTooLow {
    /// The height given, m.
    pub cg_height: f64,
    /// The narrower track, m.
    pub track: f64,
    /// The largest static stability factor accepted, g.
    pub max: f64,
    /// The least accepted, g.
    pub min: f64,
}

/// The message of [`ParamReason::CgTooLow`]: the static stability factor
/// above any vehicle's, the least height the rule allows, and the height
/// ten times the value's where that is a vehicle's.
pub(super) fn cg_too_low(c: &CgTooLow) -> String {
    let (h, track, max) = (c.cg_height, c.track, c.max);
    // A height of 0 has no stability factor to quote (it is infinite): the
    // centre of gravity on the road, which no vehicle's is.
    if h == 0.0 {
        return format!(
            "a cg_height of 0 puts the centre of gravity on the road, which no vehicle's is (and makes its static stability factor track/(2·cg_height) infinite): the rule asks for a cg_height of at least track/(2·{}) = {} m on the narrower track ({} m)",
            rounded(max, 3),
            rounded(track / (2.0 * max), 3),
            rounded(track, 4),
        );
    }
    let tips_at = track / (2.0 * h);
    let head = format!(
        "the static stability factor track/(2·cg_height) on the narrower track ({} m) is {} g, above {} g, more than any vehicle's (a road car's is 1.0–1.5 g, NHTSA; a Formula 1 car's or a kart's about 2.5–3): the rule asks for a cg_height of at least track/(2·{max}) = {} m",
        rounded(track, 4),
        rounded(tips_at, 3),
        rounded(max, 3),
        rounded(track / (2.0 * max), 3),
    );
    let tenfold = track / (2.0 * 10.0 * h);
    match (c.min..=max).contains(&tenfold) && h > 0.0 {
        true => format!(
            "{head}: is a digit slipped? {} m would give {} g",
            rounded(10.0 * h, 4),
            rounded(tenfold, 3)
        ),
        false => format!("{head}: is it in another unit, or another key's value?"),
    }
}

/// [`ParamReason::WheelbaseMismatch`]: `a` + `b` against the `wheelbase`
/// given (m), their difference in mm, and where `a` and `b` are.
pub(super) fn wheelbase_mismatch(w: &Wheelbase) -> String {
    let Wheelbase {
        a, b, wheelbase, ..
    } = *w;
    let places = if w.places.is_empty() {
        String::new()
    } else {
        format!(" ({})", w.places.join(", "))
    };
    let sum = a + b;
    let mm = 1000.0 * (wheelbase - sum);
    format!(
        "the wheelbase is {} m and a + b = {} + {} = {} m{places}: it is {} mm {} than a + b, and the two must agree to 1 mm (the wheelbase is the distance a + b between the axles); correct `a`, `b` or `wheelbase`, or leave `wheelbase` out",
        rounded(wheelbase, 6),
        rounded(a, 6),
        rounded(b, 6),
        rounded(sum, 6),
        rounded(mm.abs(), 3),
        if mm > 0.0 { "longer" } else { "shorter" },
    )
}
