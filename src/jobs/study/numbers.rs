//! The numbers of `study.csv`: a stiffness read back from N/rad into the
//! file's unit (N/deg) carries the round trip's last-bit noise
//! (`700.0000000000001`); the table shows the decimal it stands for.

/// `v` for the table: the shortest decimal of at most 15 significant
/// digits within 4 ulp of it where there is one (a stiffness read back from
/// N/rad into the file's unit: `700`, not `700.0000000000001`), else the
/// shortest decimal that reads back as `v`.
pub(super) fn csv_number(v: f64) -> String {
    if v.is_finite() && v != 0.0 {
        let near = (1..=15)
            .filter_map(|digits| format!("{v:.*e}", digits - 1).parse::<f64>().ok())
            .find(|w| (w - v).abs() <= 4.0 * f64::EPSILON * v.abs());
        if let Some(w) = near {
            return w.to_string();
        }
    }
    v.to_string()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_stiffness_read_back_from_n_per_rad_is_the_decimal_it_stands_for() {
        let k = 180.0 / std::f64::consts::PI;
        assert_eq!(csv_number(700.0 * k / k), "700");
        assert_eq!(csv_number(240.00000000000003), "240");
        assert_eq!(csv_number(339.99999999999994), "340");
        // A value that needs its digits keeps them, exactly.
        assert_eq!(csv_number(11459.155902616465), "11459.155902616465");
        assert_eq!(csv_number(0.38400000000000056), "0.38400000000000056");
        assert_eq!(csv_number(f64::NAN), "NaN");
        assert_eq!(csv_number(0.0), "0");
    }
}
