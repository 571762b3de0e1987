//! The physical limits of a range check ([`Limit`]): why a range is what
//! it is, one kind per limit, its message built from the kind. Units as
//! the key's (SI unless the key names another).

use super::*;

/// Why a range check's range is what it is ([`ParamReason::OutOfRange`]).
#[derive(Debug, Clone, Copy, PartialEq, Error)]
#[non_exhaustive]
pub enum Limit {
    /// An effect's number ([`crate::error::EffectLimit`]).
    #[error("{0}")]
    Effect(crate::error::EffectLimit),
    /// The simplified Magic Formula's shape factor C.
    #[error("a shape factor outside (0, 2] has no physical meaning")]
    ShapeFactor,
    /// A road's bank angle.
    #[error("a bank steeper than {} rad ({:.0}°; Daytona's banking is 31°, Talladega's 33°) is not a road", crate::constants::STEEPEST_BANK, crate::constants::STEEPEST_BANK.to_degrees())]
    RoadBank,
    /// A steering compliance, rad/N.
    #[error("no steering system loses more than 0.1 rad (5.7°) of road-wheel steer per kN of front axle force (1e-4 rad/N); the scenario key is in rad/N (0.003 rad/kN, the diagnosis's unit, is 3e-6 rad/N)")]
    SteeringCompliance,
    /// An aerodynamic down-force coefficient per axle, N per (m/s)².
    #[error("a Formula 1 car's down-force is about 2.7 N per (m/s)² in all (½·ρ·C_L·A with C_L·A ≈ 4.5 m²), a road car's lift a few tenths below 0; the key is k in N per (m/s)² of one axle (a down-force F in N at a speed u is k = F/u²)")]
    AeroLoad,
    /// A roll gradient, rad per m/s².
    #[error("a car rolls 2–8°/g (0.0036–0.014 rad per m/s²), a soft SUV about 10°/g; the key is in rad per m/s² (4°/g is 0.0071), and 0.05 (28°/g) is beyond any car's")]
    RollGradient,
    /// A share of the rigid-body longitudinal load transfer.
    #[error("1 is the rigid body's transfer m·ax·h/l (anti-dive and anti-squat geometry lower it); 3 times it would lift the rear axle off under 0.3 g of braking on a car with its centre of gravity at mid-wheelbase and h/l = 0.2")]
    LongitudinalLoadTransfer,
    /// A share of the longitudinal force the tyres carry.
    #[error("1 is all of m·ax carried through the tyres' friction circles (drag and rolling resistance add a little when driving); 3 times it is no car's")]
    LongitudinalForceShare,
    /// A slip-angle bin, degrees.
    #[error("a slip-angle bin wider than 2° averages the curve's rise to its peak away (a rig sweeps to about 12°, the peak lies at 3–8°); 0 keeps every sample")]
    SlipAngleBin,
    /// A pressure written in a tyre file's `[fitted_ranges]`, Pa.
    #[error("no tyre is tested above 5 MPa (a car tyre runs at 200–300 kPa, a truck's up to 1 MPa), and `identify` refuses rig data above it, so no range it writes reaches past it: the range was written in another unit (kPa written as Pa is 1000× too large) or by hand; write it in Pa, or remove the key")]
    WrittenPressure,
    /// A slip-ratio bin.
    #[error("a slip-ratio bin wider than 0.05 averages the curve's rise to its peak away (the peak lies at a slip ratio of 0.05–0.15); 0 keeps every sample")]
    SlipRatioBin,
    /// The replay step of a diagnosis.
    #[error("a replay step finer than 0.1 ms gains nothing on a log and costs memory and time in proportion, one coarser than 50 ms misses the yaw mode (a model too stiff for RK4 at the step is replayed by ROS34PW2 at it, not on a finer grid)")]
    ReplayStep,
    /// The rate of the fits' residuals, Hz.
    #[error("the fits compare model and runs at this rate and see motions up to half of it: a car's yaw and lateral response reach 1–2 Hz, which residuals at 4 Hz or less would miss or alias, so above 4 Hz (the default is 25 Hz; a rate above the logs' takes every sample)")]
    ResidualRate,
    /// The most effects a verdict names.
    #[error("the verdict names up to this many effects, so at least one")]
    MaxEffects,
    /// The upper end of a prior's 95 % range.
    #[error("a range's upper end must lie above its lower end")]
    PriorRange,
    /// A sensor's position on the car, m ahead of its centre of gravity.
    #[error("a sensor on a car lies within 5 m of its centre of gravity; the key is in m ahead of it (negative behind)")]
    SensorPosition,
    /// A prior's cornering coefficients beyond what the axle identification represents.
    #[error("the axles identified from the runs have cornering coefficients of 0.4–4000 1/rad (a softer or stiffer axle is no tyre)")]
    PriorCornering,
    /// A prior's peak friction beyond what the axle identification represents.
    #[error("the axles identified from the runs have a peak friction of 0.11–9")]
    PriorFriction,
    /// The length of a run's segment, s.
    #[error("a segment must be longer than {min} s")]
    Segment {
        /// The shortest run, s.
        min: f64,
    },
    /// The low-pass cut-off of the step-steer metrics, Hz.
    #[error("a zero-phase low-pass at f Hz rises in about 0.5/f s, a yaw-rate response in 0.1–0.5 s: below 1 Hz the filter smooths the steer step and the response themselves, and the metrics would measure the filter (5–10 Hz removes sensor noise and keeps the response)")]
    FilterCutoff,
    /// The output step of a simulation.
    #[error("rows (and RK4 steps) more than 50 ms apart miss the yaw mode")]
    OutputStep,
    /// Dormand–Prince's relative tolerance.
    #[error("a relative tolerance below 1e-14 is below rounding, above 1e-2 not a simulation")]
    RelativeTolerance,
    /// Dormand–Prince's absolute tolerance.
    #[error("the absolute tolerance (rad, rad/s) must lie in (1e-16, 1e-2]")]
    AbsoluteTolerance,
    /// Dormand–Prince's largest step.
    #[error("the largest step must lie in (1e-6, 1] s")]
    MaxStep,
    /// A manoeuvre's end.
    #[error("the run must end after it starts, {}", longest_run())]
    EndAfterStart,
    /// A manoeuvre's start.
    #[error(
        "a run starts at 0 s or later and before the {} s its end may reach",
        crate::constants::LONGEST_RUN
    )]
    StartBeforeEnd,
    /// The share of the reached lateral acceleration a design may ask.
    #[error("a design asks at most the lateral acceleration the runs reached")]
    AyShare,
    /// The longitudinal acceleration a design may ask, m/s².
    #[error("tyres give a car at most about 15 m/s² (μ ≈ 1.5) of braking or driving")]
    MaxAx,
    /// The least overshoot a step's maximum must reach, % of the step.
    #[error("the threshold is there to pass over the filter's and the noise's ringing (a few %); a well-damped car's step overshoots by tens of % (the standards' steps), and one beyond 100 % is warned of as a spin or a very lightly damped response, so a threshold beyond it would hide every overshoot worth measuring")]
    MinOvershoot,
    /// A parameter held at a value the user gives.
    #[error("no tyre model's parameter, in its file's units, lies beyond ±1e6 (a stiffness in N/rad of the largest tyres is below it); a value there stalls the fit")]
    HoldValue,
    /// A user's cap on a staged fit's iterations.
    #[error("a stage of the staged fit converges in tens to hundreds of iterations (the default cap of 150 is continued to 50 per free parameter where a stage stops short), so a cap beyond {} is no cap, only a fit that runs silently for hours where it does not converge", crate::constants::MOST_STAGE_ITERATIONS)]
    StageIterations,
    /// A manoeuvre's speed, m/s.
    #[error("the model evaluates no speed below 0.5 m/s (its slip angles divide by the speed; a slower run would run at 0.5 m/s), and a manoeuvre on a road runs below 150 m/s (540 km/h), beyond which the tyre models and the 2-DOF model are far outside what they were made for")]
    ManoeuvreSpeed,
    /// A `.tir`'s reference speed `LONGVL`, m/s.
    #[error("LONGVL is the speed the file's measurements were taken at, in m/s (the [UNITS] LENGTH per TIME), and no tyre rig or car runs beyond 150 m/s (540 km/h), the limit a rig file's and a run's speed keep to: is it in km/h (÷ 3.6) or mm/s (÷ 1000)?")]
    ReferenceSpeed,
    /// A steer frequency, Hz.
    #[error("no handling manoeuvre steers faster than 50 Hz (a driver steers below about 5 Hz, handling tests sweep to a few hertz); a faster steer only multiplies the integration steps (is the value in rad/s, or a sample rate?)")]
    SteerFrequency,
    /// A step steer's ramp.
    #[error("ISO 7401 asks for 10–90 % of the steer within 0.15 s: a linear 0–100 % ramp of at most 0.1875 s (GB/T 6323 allows 0.2 s)")]
    RampTime,
    /// The time a step steer needs to settle.
    #[error("the run must last at least 2 s after the steer reaches its final value, to reach steady state, {}", longest_run())]
    SettleTime,
    /// A front road-wheel steer angle, rad.
    #[error("no road wheel steers beyond ±45° (0.785 rad; a car's largest mean road-wheel steer is about 35–40°): steer angles are in radians, so is the value in degrees?")]
    RoadWheelSteer,
    /// A front road-wheel steer angle given in degrees.
    #[error(
        "no road wheel steers beyond ±45° (a car's largest mean road-wheel steer is about 35–40°)"
    )]
    RoadWheelSteerDegrees,
    /// A tyre's contact length `given`, m as read: one beyond 1 m is said
    /// as the millimetres it likely is, with the value given converted.
    #[error("{}", contact_length(*given))]
    ContactLength {
        /// The length as read, m.
        given: f64,
    },
    /// A tyre's cornering stiffness, N/rad.
    #[error("no tyre's cornering stiffness reaches 2e6 N/rad (a car tyre's is 5e4–1.5e5, a truck tyre's about 3e5); the key is in N/rad, per wheel: check the unit")]
    CorneringStiffness,
    /// A tyre's cornering stiffness below any tyre's: in N/deg, the value `given` said converted.
    #[error("no tyre's cornering stiffness is below 900 N/rad (a bicycle tyre's is about 5e3, a car tyre's 5e4–1.5e5); the key is in N/rad, per wheel: is the value in N/deg? multiply it by 57.3 ({} N/deg is {} N/rad)", crate::error::number::Num(*given), crate::format::rounded(given.to_degrees(), 5))]
    CorneringStiffnessInDegrees {
        /// The value given, N/rad as read.
        given: f64,
    },
    /// A `.tir` file's `FZMAX` below any tyre's largest load: in kN.
    #[error("no tyre's largest load is below 100 N (a bicycle's), and this file's nominal load is FNOMIN = {} N: loads are in N after the file's [UNITS]: is FZMAX in kN? multiply it by 1000", crate::error::number::Num(*.fnomin))]
    MfFzmaxInKn {
        /// FNOMIN, N.
        fnomin: f64,
    },
    /// A simplified Magic Formula's stiffness per unit load `B·C·D`
    /// (1/rad) below any tyre's
    /// ([`crate::tyre::sizes::MIN_CORNERING_PER_LOAD`]): `B` per degree.
    #[error("the model's cornering stiffness per unit load is B·C·D = {} 1/rad, below any tyre's (a car tyre's is about 5–45, the softest truck tyre's about 7): B is per radian: is it per degree? multiply it by 57.3 (or is D, the peak friction, far below a road's?)", crate::format::readable(*.per_load, 3))]
    MagicSimplePerDegree {
        /// B·C·D, 1/rad as read.
        per_load: f64,
    },
    /// A PAC89 file's largest cornering stiffness `a3` (N/deg), too small: in kN/deg.
    #[error("PAC89's cornering stiffness is BCD = a3·sin(2·atan(Fz/a4)), in N/deg (the model's slip angle is in degrees, its force in N), so |a3| bounds it: no tyre's is below 15 N/deg (900 N/rad; a car tyre's a3 is 1000–3000 N/deg): is the value in kN/deg? multiply it by 1000")]
    Pac89CorneringStiffnessInKn,
    /// A UniTire file's cornering stiffness per unit load `p3`, too small: per degree.
    #[error("UniTire's cornering stiffness is K = Fz·(p3 + p4·Fzn + p5·Fzn²) per unit tan α, so p3 (`p[2]`) is K/Fz at light load, 10–25 for a road or racing tyre: no tyre's is below 0.9: are p3, p4 and p5 per degree? multiply them by 57.3")]
    UniTireCorneringStiffness,
    /// A UniTire file's longitudinal slip stiffness per unit load `p3`, too
    /// small: per percent of slip.
    #[error("UniTire's longitudinal slip stiffness is K = Fz·(p3 + p4·Fzn + p5·Fzn²) per unit slip ratio Sx, so p3 (`p[2]`) is K/Fz at light load, 10–30 for a road or racing tyre: no tyre's is below 0.9: are p3, p4 and p5 per percent of slip? multiply them by 100")]
    UniTireSlipStiffness,
    /// A tyre's reference or rated load, N.
    #[error("a tyre carries 100 N (a bicycle) to 1e5 N (a mining truck); the key is in N: is the value in kN? (4 kN is 4000)")]
    TyreLoad,
    /// A tyre's friction coefficient.
    #[error(
        "no tyre's friction coefficient reaches 5 (racing slicks reach about 1.8): check the value"
    )]
    TyreFriction,
    /// A road's friction, a scale on the tyres' own.
    #[error("the road's friction scales the tyres' own (1 = as measured on the rig, 0.1–0.3 on ice); no road grips three times a tyre's rig surface: is it a speed or a percentage?")]
    RoadFriction,
    /// A pneumatic trail, m.
    #[error("a tyre's pneumatic trail is a few centimetres; the key is in metres: is the value in millimetres? (30 mm is 0.03)")]
    PneumaticTrail,
    /// A Magic Formula file's unloaded radius `given`, m, and the unit slip its direction says.
    #[error("{}", unloaded_radius(*given))]
    UnloadedRadius {
        /// The radius as read, m.
        given: f64,
    },
    /// A Magic Formula coefficient, dimensionless.
    #[error("no coefficient of a published Magic Formula file reaches ±1e6 (their dimensionless coefficients stay within about ±2,000): a value beyond is no tyre's")]
    MfCoefficient,
    /// A Magic Formula stiffness (N/m) or pressure (Pa).
    #[error("a tyre's vertical stiffness (N/m) and pressures (Pa) lie below 1e8 in SI (2e6 N/m, 1e6 Pa at most): check the value against the file's [UNITS]")]
    MfDimensional,
    /// A Magic Formula file's inflation pressure (`NOMPRES`, `INFLPRES`),
    /// Pa, outside any tyre's: `given` as read, `unit` the index in
    /// [`Limit::PRESSURE_UNITS`] of the unit it likely is in, `nominal`
    /// whether the key is `NOMPRES`, `apart` whether the other key lies
    /// that unit's factor above it.
    #[error("{}", tyre_pressure(*given, *unit, *nominal, *apart))]
    TyrePressure {
        /// The value as read, Pa.
        given: f64,
        /// The likely unit's index in [`Limit::PRESSURE_UNITS`].
        unit: Option<u8>,
        /// The key is `NOMPRES` (else `INFLPRES`).
        nominal: bool,
        /// The other pressure key is about the unit's factor above it.
        apart: bool,
    },
}

/// The words of a contact length `given` (m as read) out of range: above
/// it, the millimetres it likely is converted (`contact_length = 160`:
/// "160 mm is 0.16", where a fixed 180 mm was said whatever the value).
fn contact_length(given: f64) -> String {
    let limit = "no tyre's contact patch is longer than 1 m (a car tyre's is 0.1–0.25 m, a truck's about 0.3 m); the key is in metres";
    // The limit is `tyre::sizes::MAX_CONTACT_LENGTH`'s 1 m, which the words
    // say (the errors sit below the tyres and do not import them).
    if given > 1.0 {
        let metres = crate::format::rounded(given / 1000.0, 6);
        return format!(
            "{limit}: is the value in millimetres? ({} mm is {metres})",
            crate::error::number::Num(given)
        );
    }
    limit.to_string()
}

/// The upper end of a run's `end`, and why: the rows a history holds.
fn longest_run() -> String {
    let longest = crate::constants::LONGEST_RUN;
    format!(
        "and end by {longest} s ({:.1} h): a history holds at most 2000001 rows, a first and one every [simulation] `step` of at most 0.05 s after it (2000000 steps of 0.05 s are {longest} s, about 0.3 GB of history.csv)",
        longest / 3600.0
    )
}
