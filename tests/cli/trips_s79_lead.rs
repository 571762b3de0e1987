//! What the lead fixed of a fresh user's findings in session 79: a channel
//! name under `[channels]` that is also a table of the campaign sent
//! "before the first [table]".

use super::*;

/// `[channels] roll = 0.01` in a campaign (which has a `[roll]` table of
/// its own) was refused with "(it belongs before the first [table])", a
/// place where `roll = 0.01` is no more valid; now the channels the table
/// knows are listed, with no place to move it to.
#[test]
fn a_channel_named_like_a_table_of_the_campaign_is_sent_nowhere() {
    let dir = tempfile::tempdir().unwrap();
    let camp = synth_campaign(
        dir.path(),
        "camp",
        &["--effects", "sensor_delay", "--seed", "1"],
    );
    let file = camp.join("vehicle.toml");
    let text = fs::read_to_string(&file).unwrap();
    fs::write(&file, format!("{text}\n[channels]\nroll = 0.01\n")).unwrap();
    let e = fails_cleanly("diagnose", &camp, dir.path());
    assert!(
        e.contains(
            "`channels.roll`: unknown field `roll`, expected one of `yaw_rate`, `ay`, `beta`"
        ),
        "{e}"
    );
    assert!(!e.contains("belongs"), "{e}");
}
