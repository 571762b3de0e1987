//! Other names engineers and loggers write for the columns the readers
//! take (see [`super`]): `gamma` or `inclination` for `camber`,
//! `slip_angle` for `alpha`, `slip_ratio` for `kappa`, `steering_angle` for
//! `steer`, `sideslip` for `beta`, `velocity` for `speed`. None is read
//! under its other name (a `steering_angle` may be the handwheel's, a
//! `gamma` in degrees): each is named with a did-you-mean where the column
//! it stands for is missing, so that it is never ignored silently (a
//! `gamma` column left unread pooled a rig file's three cambers as 0).

/// Other names (lower-case, without `_`, `-` or spaces) and the column each
/// stands for. Greek letters as some exports write them.
const ALIASES: [(&str, &str); 29] = [
    ("gamma", "camber"),
    ("γ", "camber"),
    ("inclination", "camber"),
    ("inclinationangle", "camber"),
    ("camberangle", "camber"),
    ("slipangle", "alpha"),
    ("tyreslipangle", "alpha"),
    ("tireslipangle", "alpha"),
    ("α", "alpha"),
    ("slipratio", "kappa"),
    ("longitudinalslip", "kappa"),
    ("κ", "kappa"),
    ("steeringangle", "steer"),
    ("steerangle", "steer"),
    ("roadwheelangle", "steer"),
    ("wheelangle", "steer"),
    ("sideslip", "beta"),
    ("sideslipangle", "beta"),
    ("bodyslipangle", "beta"),
    ("β", "beta"),
    ("velocity", "speed"),
    ("vx", "speed"),
    ("forwardspeed", "speed"),
    ("yawvelocity", "yaw_rate"),
    ("lateralacceleration", "ay"),
    ("latacc", "ay"),
    ("verticalload", "fz"),
    ("normalload", "fz"),
    ("inflationpressure", "pressure"),
];

/// The column among `among` that the header's `h` is another name of
/// ([`ALIASES`]), matched without case, separators, or a unit written
/// after it in brackets (`Slip Angle [deg]`).
pub(super) fn alias_of<'a>(h: &str, among: &[&'a str]) -> Option<&'a str> {
    let name = h.split(['[', '(']).next().unwrap_or_default();
    let plain = plain(name);
    let (_, ours) = ALIASES.iter().find(|(other, _)| *other == plain)?;
    among.iter().copied().find(|n| n == ours)
}

/// A header name as the readers compare names: lower-case, without `_`,
/// `-` or spaces (`Yaw Rate`, `yaw-rate` and `YawRate` are `yawrate`, as
/// `yaw_rate` is), so that a name is read alike whatever its case and
/// separators.
pub(super) fn plain(name: &str) -> String {
    name.to_lowercase()
        .chars()
        .filter(|c| !matches!(c, '_' | '-' | ' '))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn other_names_are_found_only_among_the_columns_asked_for() {
        assert_eq!(alias_of("gamma", &["alpha", "camber"]), Some("camber"));
        assert_eq!(alias_of("Slip_Angle [deg]", &["alpha"]), Some("alpha"));
        assert_eq!(alias_of("steering-angle", &["steer"]), Some("steer"));
        assert_eq!(alias_of("sideslip", &["beta"]), Some("beta"));
        // Not a column this reader takes: nothing to hint at.
        assert_eq!(alias_of("gamma", &["alpha"]), None);
        assert_eq!(alias_of("gammas", &["camber"]), None);
    }

    #[test]
    fn a_plain_name_drops_case_and_separators_only() {
        for h in ["Yaw Rate", "yaw-rate", "YawRate", "yaw_rate", " yaw_rate "] {
            assert_eq!(plain(h), "yawrate", "{h}");
        }
        assert_eq!(plain("Steer"), "steer");
        assert_ne!(plain("yaw.rate"), "yawrate");
    }
}
