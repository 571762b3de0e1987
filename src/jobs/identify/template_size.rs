//! The size fields a fit from a `.tir` template keeps (the template's
//! unloaded radius, width and vertical stiffness, SI units), each held
//! and said with what it enters, and where the template's nominal load
//! lies far from the data's, said as likely another tyre's
//! (`identify/template_size.rs`). A field given with `--hold`, or that
//! the template leaves at 0 (absent), is not said here.

use crate::identify::mf_staged::MfRow;
use crate::identify::template_size::SizeField;
use crate::identify::{ConstantFrom, HeldFor};
use crate::tyre::mf::MagicFormula;

/// The size fields of `template` the fit on `rows` keeps, held with
/// their reason; none without a template or rows with loads.
pub(super) fn kept(
    template: Option<&MagicFormula>,
    rows: &[MfRow],
    hold: &[(String, f64)],
) -> Vec<super::holds::Held> {
    let Some(t) = template else {
        return Vec::new();
    };
    let Some(data_load) = super::nompres::median(rows.iter().map(|r| r.fz).collect()) else {
        return Vec::new();
    };
    let c = &t.coefficients;
    let value = |f: SizeField| match f {
        SizeField::UnloadedRadius => c.UNLOADED_RADIUS,
        SizeField::Width => c.WIDTH,
        SizeField::VerticalStiffness => c.VERTICAL_STIFFNESS,
    };
    SizeField::ALL
        .into_iter()
        .filter(|f| value(*f) > 0.0 && !hold.iter().any(|(n, _)| n == f.key()))
        .map(|field| super::holds::Held {
            name: field.key().into(),
            value: value(field),
            applied: true,
            reason: HeldFor::Constant {
                from: ConstantFrom::TemplateSize {
                    field,
                    template_fnomin: c.FNOMIN,
                    data_load: (data_load / 10.0).round() * 10.0,
                },
            },
        })
        .collect()
}
