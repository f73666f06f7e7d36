pub mod box_room;
pub mod compare;
pub mod corpus;
pub mod primitives;
pub mod radiance;
pub mod small_scenes;
