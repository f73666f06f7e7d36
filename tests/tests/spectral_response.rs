//! The sensor model's per-channel spectral response (issue 3): each Bayer channel answers a
//! scene's spectrum through its own sensitivity, so a device calibrated under D65 misreads a
//! bluer or redder sky by exactly `Σ w_c rel_c / Σ w_c - 1`.
//!
//! Data: `shared/data/spectral` (see its README): CIE V(λ), the CIE daylight basis, the
//! tabulated D65, and the NPL-measured sensitivities of a Bayer CMOS camera (Nikon D5100),
//! standing in for the MT9P031's, whose curves the data folder does not hold.

use glam::DVec3;
use skylux_hps::camera::{CameraModel, DeviceConfig};
use skylux_hps::campaign::{BayerPattern, Readout};
use skylux_hps::hdr::{merge, Exposure, GroupGeometry, MapFlag};
use skylux_sim::sensor::spectral::{cie_daylight, read_columns};
use skylux_sim::sensor::{ChannelResponse, FrameRenderer, Noise, SpectralData};
use std::path::PathBuf;

fn data_dir() -> PathBuf {
    std::env::var_os("SKYLUX_DATA_DIR")
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../shared/data"))
}

fn d65() -> skylux_sim::sensor::spectral::Curve {
    let path = data_dir().join("spectral/cie_illuminant_D65.csv");
    read_columns(&path, &["relative_spd"]).unwrap().remove(0)
}

#[test]
fn the_daylight_formula_reproduces_the_tabulated_d65_for_every_channel() {
    let data = SpectralData::load(&data_dir()).unwrap();
    // CIE 15:2004: D65 is the daylight of CCT 6504 K.
    let formula = cie_daylight(&data.daylight_basis, 6504.0);
    let r = ChannelResponse::of(&data, &formula, &d65());
    for (c, rel) in r.relative.iter().enumerate() {
        assert!((rel - 1.0).abs() < 2e-3, "channel {c}: {rel}");
    }
    assert_eq!(
        ChannelResponse::of(&data, &d65(), &d65()),
        ChannelResponse::GREY
    );
}

#[test]
fn bluer_daylight_raises_blue_and_lowers_red() {
    let data = SpectralData::load(&data_dir()).unwrap();
    let calibration = d65();
    let at = |cct: f64| {
        ChannelResponse::of(
            &data,
            &cie_daylight(&data.daylight_basis, cct),
            &calibration,
        )
    };
    let ccts = [4000.0, 5000.0, 6504.0, 9000.0, 15000.0, 25000.0];
    let rs: Vec<_> = ccts.iter().map(|&t| at(t)).collect();
    for w in rs.windows(2) {
        assert!(w[1].relative[2] > w[0].relative[2], "{rs:?}");
        assert!(w[1].relative[0] < w[0].relative[0], "{rs:?}");
    }
    for (t, r) in ccts.iter().zip(&rs) {
        println!(
            "{t:>6} K: rel R {:.4} G {:.4} B {:.4}, luminance error with default weights {:+.2} %",
            r.relative[0],
            r.relative[1],
            r.relative[2],
            100.0 * r.luminance_error(DeviceConfig::default().response.weights)
        );
    }
}

#[test]
fn the_hdr_map_of_a_blue_sky_is_off_by_exactly_the_predicted_mismatch() {
    let data = SpectralData::load(&data_dir()).unwrap();
    let response = ChannelResponse::of(&data, &cie_daylight(&data.daylight_basis, 15000.0), &d65());
    let device = DeviceConfig::default();
    let predicted = response.luminance_error(device.response.weights);
    assert!(
        predicted.abs() > 5e-3,
        "the case must show a mismatch: {predicted}"
    );
    let camera = CameraModel::new(device.clone());
    let readout = Readout {
        col_start: 1200,
        row_start: 900,
        skip: 1,
        bin: 1,
    };
    let (w, h) = (64, 48);
    let geometry = GroupGeometry::new(&camera, &readout, w, h);
    let renderer = FrameRenderer {
        camera: &camera,
        readout,
        raw_width: w,
        raw_height: h,
        footprint: Default::default(),
        small_sources: vec![],
    };
    // A uniform sky, bright enough for ~2000 DN: rounding is below 0.05 %.
    let field = |_: DVec3| 8.0e3;
    let scene = renderer.scene(&field);
    let t = 2.0e3 / (8.0e3 / device.response.cg);
    let frame =
        renderer.render_scene_spectral(&scene, t, 1.0, Noise::None, &response, BayerPattern::GRBG);
    let map = merge(
        &[Exposure {
            frame: &frame,
            exposure_s: t,
            gain: 1.0,
        }],
        &device,
        BayerPattern::GRBG,
        &geometry,
    )
    .unwrap();
    let errors: Vec<f64> = (0..map.flags.len())
        .filter(|&i| map.flags[i] == MapFlag::Valid)
        .map(|i| map.luminance_cd_m2[i] as f64 / 8.0e3 - 1.0)
        .collect();
    assert!(errors.len() > w * h / 8, "{} valid groups", errors.len());
    let mean = errors.iter().sum::<f64>() / errors.len() as f64;
    println!("15000 K sky, D65 calibration: predicted {predicted:+.4}, measured {mean:+.4}");
    assert!((mean - predicted).abs() < 1e-3, "{mean} vs {predicted}");
}

#[test]
fn the_sensor_model_images_a_scene_through_the_channel_response() {
    use skylux_sim::mt9p031::{Mt9p031, PixelSource, Registers, SceneSource, ShutterOverhead};
    let data = SpectralData::load(&data_dir()).unwrap();
    let response = ChannelResponse::of(&data, &cie_daylight(&data.daylight_basis, 15000.0), &d65());
    let mut device = DeviceConfig::default();
    device.noise.read_noise_dn = 0.0;
    let mut source = SceneSource {
        camera: CameraModel::new(device.clone()),
        luminance_cd_m2: Box::new(|_| 2.0e5),
        noise_seed: None,
        channel_response: response,
        small_sources: vec![],
    };
    // A 64 x 48 window in the middle of the array, 400 rows of exposure at 96 MHz.
    let mut registers = Registers::default();
    registers.write(0x01, 54 + 948); // Row_Start
    registers.write(0x02, 16 + 1264); // Column_Start
    registers.write(0x03, 47); // Row_Size
    registers.write(0x04, 63); // Column_Size
    registers.write(0x09, 400); // Shutter_Width_Lower
    let settings = Mt9p031::settings_of(&registers, ShutterOverhead::VariantA);
    let frame = source.frame(&settings, 96e6, 0);
    assert_eq!((frame.width, frame.height), (64, 48));
    // Mean of each colour (GRBG), black subtracted.
    let black = device.sensor.black_level_dn;
    let mean = |dx: usize, dy: usize| {
        let v: Vec<f64> = (0..frame.height / 2)
            .flat_map(|gy| (0..frame.width / 2).map(move |gx| (gx, gy)))
            .map(|(gx, gy)| {
                frame.samples_dn[(2 * gy + dy) * frame.width + 2 * gx + dx] as f64 - black
            })
            .collect();
        v.iter().sum::<f64>() / v.len() as f64
    };
    let (g, r, b) = (mean(0, 0), mean(1, 0), mean(0, 1));
    assert!(g > 50.0 && g < 4000.0, "signal {g} DN");
    let (want_br, want_rg) = (
        response.relative[2] / response.relative[0],
        response.relative[0] / response.relative[1],
    );
    println!(
        "B/R {:.4} (want {want_br:.4}), R/G {:.4} (want {want_rg:.4})",
        b / r,
        r / g
    );
    // Vignetting and the group-centre lookup are shared by the channels; shot noise is the
    // only difference left, at this signal well below 1 %.
    assert!((b / r / want_br - 1.0).abs() < 0.01);
    assert!((r / g / want_rg - 1.0).abs() < 0.01);
}
