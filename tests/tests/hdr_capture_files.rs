//! The HDR path through files: a simulated capture written in the campaign format, read back
//! by the one campaign reader, merged, written as OpenEXR and read back.

use skylux_hps::hdr::{map_capture, read_exr, MapFlag};

#[test]
fn capture_files_merge_and_round_trip_through_exr() {
    let dir = tempfile::tempdir().unwrap();
    let device = skylux_sim::capture::write_example_capture(dir.path(), 7).unwrap();
    let merged = map_capture(dir.path(), &device).unwrap();
    assert_eq!((merged.map.width, merged.map.height), (64, 48));
    assert!(
        merged
            .map
            .flags
            .iter()
            .filter(|f| **f == MapFlag::Valid)
            .count()
            > 3000
    );
    let out = dir.path().join("map.exr");
    skylux_hps::hdr::write_exr(&out, &merged.map, &device, &merged.capture.readout).unwrap();
    let (back, back_device, back_readout) = read_exr(&out).unwrap();
    assert_eq!(back_device, device);
    assert_eq!(back_readout, merged.capture.readout);
    assert_eq!(back.flags, merged.map.flags);
    for (a, b) in back.luminance_cd_m2.iter().zip(&merged.map.luminance_cd_m2) {
        assert!(a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan()));
    }
}
