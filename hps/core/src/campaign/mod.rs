//! The measurement campaign format (shared/spec/campaign.md): the one reader of captures and
//! raw frames, shared by the HDR synthesis, the loop and the simulator that writes campaigns.

mod campaign_file;
mod capture;
mod luxmeters;
mod raw_frame;

pub use campaign_file::{
    Campaign, CampaignConfig, CampaignError, CampaignFiles, CaptureEntry, Site,
};
pub use capture::{BayerPattern, CaptureConfig, CaptureError, Channel, ExposureEntry, Readout};
pub use luxmeters::{
    parse_luxmeters, read_luxmeters, write_luxmeters, LuxmeterError, LuxmeterReading,
};
pub use raw_frame::{RawFrame, RawFrameError, MAX_SAMPLE_DN};
