//! Why the device model could not be built.

/// Why the model could not be built.
#[derive(Debug, thiserror::Error)]
pub enum ModelError {
    #[error(transparent)]
    Scene(#[from] crate::scene::SceneError),
    #[error(transparent)]
    Sensors(#[from] crate::scene::SensorsError),
    #[error(transparent)]
    Engine(#[from] crate::engine::EngineError),
    #[error(transparent)]
    Device(#[from] crate::camera::DeviceError),
    #[error(transparent)]
    Capture(#[from] crate::hdr::CaptureMapError),
    #[error("{0}")]
    Sun(String),
}
