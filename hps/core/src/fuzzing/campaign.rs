//! The campaign format's files (`../shared/spec/campaign.md`): `campaign.toml`,
//! `capture.toml`, raw PGM frames, `luxmeters.csv` and `pyranometer.csv`, plus the
//! irradiance station records beside them. The first byte chooses the reader, so one corpus
//! holds every kind and libFuzzer can splice between them.

use crate::campaign::{parse_luxmeters, CampaignConfig, CaptureConfig, RawFrame};
use crate::io::irradiance::{
    parse_irradiance_csv, parse_pyranometer_csv, ReadOptions, StampConvention,
};
use chrono::TimeDelta;
use std::path::Path;

/// The readers, in the order of the selector byte (modulo their count).
const READERS: [fn(&[u8]); 6] = [
    campaign_toml,
    capture_toml,
    pgm,
    luxmeters_csv,
    pyranometer_csv,
    irradiance_csv,
];

pub(super) fn campaign(bytes: &[u8]) {
    if let Some((selector, rest)) = bytes.split_first() {
        READERS[*selector as usize % READERS.len()](rest);
    }
}

fn campaign_toml(bytes: &[u8]) {
    if let Err(e) = CampaignConfig::parse(&super::checks::text(bytes), Path::new("campaign.toml")) {
        super::checks::assert_names(&e.to_string(), "campaign.toml");
    }
}

fn capture_toml(bytes: &[u8]) {
    if let Err(e) = CaptureConfig::parse(&super::checks::text(bytes), Path::new("capture.toml")) {
        super::checks::assert_names(&e.to_string(), "capture.toml");
    }
}

fn pgm(bytes: &[u8]) {
    match RawFrame::parse(bytes, Path::new("e0.pgm")) {
        Ok(f) => assert_eq!(f.samples_dn.len(), f.width * f.height),
        Err(e) => super::checks::assert_names(&e.to_string(), "e0.pgm"),
    }
}

fn luxmeters_csv(bytes: &[u8]) {
    if let Err(e) = parse_luxmeters(Path::new("luxmeters.csv"), &super::checks::text(bytes)) {
        super::checks::assert_names(&e.to_string(), "luxmeters.csv");
    }
}

fn pyranometer_csv(bytes: &[u8]) {
    if let Err(e) = parse_pyranometer_csv("pyranometer.csv", &super::checks::text(bytes)) {
        super::checks::assert_names(&e.to_string(), "pyranometer.csv");
    }
}

/// A station's one-minute record, stamped at the interval's end.
fn irradiance_csv(bytes: &[u8]) {
    let options = ReadOptions::new(StampConvention::IntervalEnd, TimeDelta::minutes(1));
    if let Err(e) = parse_irradiance_csv("station.csv", &super::checks::text(bytes), &options) {
        super::checks::assert_names(&e.to_string(), "station.csv");
    }
}
