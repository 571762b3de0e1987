//! The numbers of `study.csv`, written as the project writes a physical
//! result in a file meant for people ([`crate::format::carried`], nine
//! significant digits): a stiffness read back from N/rad into the file's
//! unit (N/deg) carries the round trip's last-bit noise
//! (`700.0000000000001`), a metric the arithmetic's (`0.38630000000000125`);
//! the table shows the decimal they stand for (`700`, `0.3863`).

/// Significant digits of a number in the table: more than any metric or
/// stiffness carries, fewer than the arithmetic's last bits.
pub(super) const DIGITS: usize = 9;

/// `v` for the table ([`DIGITS`] significant digits, no negative zero).
pub(super) fn csv_number(v: f64) -> String {
    crate::format::carried(v, DIGITS)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_number_is_the_decimal_it_stands_for() {
        let k = 180.0 / std::f64::consts::PI;
        assert_eq!(csv_number(700.0 * k / k), "700");
        assert_eq!(csv_number(240.00000000000003), "240");
        assert_eq!(csv_number(339.99999999999994), "340");
        assert_eq!(csv_number(0.386000000000001), "0.386");
        // Nine significant digits, not the arithmetic's seventeen.
        assert_eq!(csv_number(11459.155902616465), "11459.1559");
        assert_eq!(csv_number(0.38400000000000056), "0.384");
        assert_eq!(csv_number(-0.00416391486344061), "-0.00416391486");
        assert_eq!(csv_number(0.0), "0");
    }
}
