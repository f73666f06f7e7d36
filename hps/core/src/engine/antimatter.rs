//! RADIANCE's `antimatter` (src/rt/m_clip.c): closed volumes inside which the surfaces of the
//! listed modifiers vanish; where a ray leaves such a volume into an object of its first
//! modifier, the volume's own surface is shaded as that modifier's material, turned around.
//!
//! RADIANCE follows each ray's ancestry (the set of antimatter volumes it has entered); with
//! the viewpoint outside every volume, as the manual requires, that is the same as asking
//! geometrically whether a point lies inside a volume, which [`World`](super::world::World)
//! does with the nearest surface of the volume along the ray: leaving it means inside.

use crate::scene::ModifierRef;
use std::collections::HashMap;

/// The antimatter of a scene, indexed by primitive.
#[derive(Clone, Debug, Default)]
pub struct Antimatter {
    volumes: Vec<Volume>,
    /// Per primitive: the volume it bounds (it is a surface of antimatter), if any.
    volume_of: Vec<Option<u32>>,
    /// Per primitive: its own modifier, what antimatter subtracts (m_clip compares `omod`).
    modifier_of: Vec<ModifierRef>,
    /// The volume of each antimatter modifier, as the world's primitives are added.
    by_modifier: HashMap<ModifierRef, u32>,
}

#[derive(Clone, Debug)]
struct Volume {
    subtracted: Vec<ModifierRef>,
    /// The first modifier, unless `void`: it shades the volume's surface where a ray leaves
    /// the volume into one of its objects.
    shaded_as: Option<ModifierRef>,
}

impl Antimatter {
    /// Records the next primitive: its own modifier, and for a surface of antimatter
    /// (`antimatter_modifier`, the `antimatter` definition on its chain) the modifiers it
    /// subtracts.
    pub fn push(
        &mut self,
        modifier: ModifierRef,
        antimatter: Option<(ModifierRef, &[ModifierRef])>,
    ) {
        self.modifier_of.push(modifier);
        let volume = antimatter.map(|(key, subtracted)| {
            let next = self.volumes.len() as u32;
            *self.by_modifier.entry(key).or_insert_with(|| {
                self.volumes.push(Volume {
                    subtracted: subtracted.to_vec(),
                    shaded_as: subtracted
                        .first()
                        .copied()
                        .filter(|m| *m != ModifierRef::Void),
                });
                next
            })
        });
        self.volume_of.push(volume);
    }

    /// Whether the scene has any antimatter at all.
    pub fn is_empty(&self) -> bool {
        self.volumes.is_empty()
    }

    /// The volume primitive `p` bounds, if it is a surface of antimatter.
    pub fn volume_of(&self, p: u32) -> Option<u32> {
        self.volume_of.get(p as usize).copied().flatten()
    }

    /// The modifier whose objects shade volume `v`'s surface, if not `void`.
    pub fn shaded_as(&self, v: u32) -> Option<ModifierRef> {
        self.volumes[v as usize].shaded_as
    }

    /// Whether primitive `p` has modifier `m`.
    pub fn has_modifier(&self, p: u32, m: ModifierRef) -> bool {
        self.modifier_of.get(p as usize) == Some(&m)
    }

    /// The volumes that subtract primitive `p`.
    pub fn subtracting(&self, p: u32) -> impl Iterator<Item = u32> + '_ {
        let m = self.modifier_of[p as usize];
        (0..self.volumes.len() as u32)
            .filter(move |&v| self.volumes[v as usize].subtracted.contains(&m))
    }
}
