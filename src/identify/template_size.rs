//! The size of a tyre a `.tir` template gives and a fit keeps: its
//! unloaded radius `R0` (m), width (m) and vertical stiffness (N/m). Rig
//! forces and moments do not measure them (a rig file carries no loaded
//! radius column, FORMATS.md), so a fit from a template writes the
//! template's, and a truck template (`Truck_430_50R38.tir`, R0 0.6731 m,
//! FNOMIN 30 kN) on an FSAE tyre's rig data (0.4–2.9 kN) wrote a truck's
//! size without a word. What each enters (MF 6.1/6.2, Pacejka 2012 ch. 4
//! and the TNO equations): `R0` scales the aligning moment's residual
//! torque `Dr ∝ R0·Fz` and trail `Dt ∝ R0·Fz/FNOMIN` (the fitted `QDZ*`
//! absorb it, so the fitted Mz is the data's but the coefficients are
//! read at this R0), the combined moment's arm `SSZ*·R0`, the overturning
//! and rolling resistance moments (`R0·Fz·QSX*`, `R0·FNOMIN·QSY*`) and
//! the loaded and effective rolling radius; the width enters the loaded
//! radius's camber term (MF 6.2); the vertical stiffness the load–
//! deflection law, so the loaded radius at a load. Forces (`Fx`, `Fy`)
//! read none of them. A template whose nominal load lies more than
//! [`OTHER_SIZE`] times from the data's median load is taken for another
//! size of tyre than the data's, and the kept size is said as likely
//! wrong with those numbers.

use serde::Serialize;

/// How far (a factor either way) a template's `FNOMIN` may lie from the
/// data's median load before its size is said to be likely another
/// tyre's: the FSAE template `fsae190_50R10.tir` (6 kN) lies 3.7 times
/// above the Hoosier rig's 1640 N median for a tyre of that class; the
/// truck's 30 kN lies 18 times above.
pub const OTHER_SIZE: f64 = 4.0;

/// A size field of a `.tir` template that a fit keeps.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum SizeField {
    /// `UNLOADED_RADIUS`, m.
    UnloadedRadius,
    /// `WIDTH`, m.
    Width,
    /// `VERTICAL_STIFFNESS`, N/m.
    VerticalStiffness,
}

impl SizeField {
    /// Every size field, in the file's order.
    pub const ALL: [SizeField; 3] = [
        SizeField::UnloadedRadius,
        SizeField::Width,
        SizeField::VerticalStiffness,
    ];

    /// Its key in a `.tir`.
    pub fn key(self) -> &'static str {
        match self {
            SizeField::UnloadedRadius => "UNLOADED_RADIUS",
            SizeField::Width => "WIDTH",
            SizeField::VerticalStiffness => "VERTICAL_STIFFNESS",
        }
    }

    /// What the written file reads it in (module notes).
    pub fn enters(self) -> &'static str {
        match self {
            SizeField::UnloadedRadius => {
                "the aligning moment's residual torque and trail (Dr ∝ R0·Fz, Dt ∝ R0·Fz/FNOMIN: the fitted QDZ* absorb it, so the fitted Mz is these data's but its coefficients are read at this radius), the combined moment's arm (SSZ*·R0), the overturning and rolling resistance moments (R0·Fz·QSX*, R0·FNOMIN·QSY*) and the loaded and effective rolling radius; not the forces"
            }
            SizeField::Width => {
                "the loaded radius's camber term (MF 6.2, with ASPECT_RATIO); not the forces or moments"
            }
            SizeField::VerticalStiffness => {
                "the vertical load–deflection law, so the loaded radius at a load; not the forces or moments"
            }
        }
    }
}

/// The words of a template's size field `field` kept: whose it is, what
/// it enters, and where the template's nominal load (`template_fnomin`,
/// N) lies more than [`OTHER_SIZE`] times from the data's median load
/// (`data_load`, N), that it is likely another tyre's.
pub fn kept_said(field: SizeField, template_fnomin: f64, data_load: f64) -> String {
    let ratio = template_fnomin / data_load;
    let other = if !(1.0 / OTHER_SIZE..=OTHER_SIZE).contains(&ratio) {
        format!(
            "; warning: the template's FNOMIN {} N is {} times the data's median load {} N, so the template is likely another size of tyre than the data's, and so is this value",
            crate::format::exact(template_fnomin),
            crate::format::rounded(ratio, 3),
            crate::format::exact(data_load)
        )
    } else {
        String::new()
    };
    format!(
        "the template's, kept: rig forces and moments do not measure it; it enters {}{other}; to give this tyre's, --hold {}=VALUE",
        field.enters(),
        field.key()
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The truck template on the Hoosier rig's loads is said to be
    /// another size, with the numbers; the FSAE template is not.
    #[test]
    fn a_template_far_from_the_datas_loads_is_said_to_be_another_size() {
        let truck = kept_said(SizeField::UnloadedRadius, 30000.0, 1640.0);
        assert!(truck.contains("; warning: the template's FNOMIN 30000 N is 18.3 times the data's median load 1640 N"), "{truck}");
        assert!(
            truck.ends_with("to give this tyre's, --hold UNLOADED_RADIUS=VALUE"),
            "{truck}"
        );
        let fsae = kept_said(SizeField::Width, 6000.0, 1640.0);
        assert!(!fsae.contains("warning"), "{fsae}");
        assert!(kept_said(SizeField::Width, 300.0, 1640.0).contains("is 0.183 times"));
    }
}
