//! The traceable scene: surfaces with their materials under a BVH, and the distant sources.

use super::antimatter::Antimatter;
use super::bvh::Bvh;
use super::bvh_unit::{BvhUnit, UnitTreeError};
use super::error::EngineError;
use super::function::build::{self, resolve};
use super::function::loader::FunctionLoader;
use super::material::{
    Emitter, HitPoint, Material, ShadowCrossing, SourceCrossing, VirtualSourceReflectance,
};
use super::portal::Portals;
use super::ray::{Ray, FTINY};
use super::sampling::basis;
use super::shapes::{PreparedCone, PreparedPolygon, Primitive, ShapeHit};
use super::sky::{source_seen, DistantEmitter, DistantKind, SkyFunction};
use super::sky_sampling::SkyDistribution;
use super::slab::{BoxTest, SlabTest};
use crate::fpga::bvh_unit::BvhUnitBackend;
use crate::scene::{DistantSource, Modifier, ModifierKind, Scene, Shape, Surface};
use glam::DVec3;

/// Distance under which a ray leaving a curved surface ignores it (RADIANCE's `FTINY`, in
/// metres); flat surfaces are excluded by identity instead.
const CURVED_SELF_HIT_M: f64 = FTINY;
/// Most surfaces a shadow ray passes through (glass panes, invisible surfaces) before it is
/// taken as blocked: a guard against a pathological stack of coincident panes.
const MAX_SHADOW_CROSSINGS: usize = 64;

/// A ray's closest surface hit.
#[derive(Clone, Copy, Debug)]
pub struct Hit {
    pub t_m: f64,
    pub normal: DVec3,
    /// Index of the primitive in the world.
    pub primitive: u32,
}

impl Hit {
    /// This hit of a ray along unit `direction`, at `point_m`, as a material resolves it.
    pub fn as_seen(&self, point_m: DVec3, direction: DVec3, flat: bool) -> HitPoint {
        HitPoint {
            point_m,
            direction,
            normal: self.normal,
            distance_m: self.t_m,
            flat,
        }
    }
}

/// The scene as the integrator sees it.
pub struct World {
    primitives: Vec<Primitive>,
    material_of: Vec<u32>,
    materials: Vec<Material>,
    bvh: Bvh,
    box_test: Box<dyn BoxTest + Send>,
    /// The box test is the software [`SlabTest`]: traversal then calls it directly.
    software_box_test: bool,
    /// The BVH ray unit (or its model), when attached: it traverses, the HPS finishes.
    bvh_unit: Option<BvhUnit>,
    distant: Vec<DistantEmitter>,
    environment: Option<Environment>,
    /// Surface names, per primitive (for naming portals).
    names: Vec<String>,
    /// Polygons that may serve as portals (glass or invisible), with their vertices.
    portal_candidates: Vec<(u32, Vec<DVec3>)>,
    portals: Portals,
    /// Polygons of `BSDF` material open to the outside (windows with blinds, shades):
    /// directions towards them are mixed into the continuation at Lambertian vertices
    /// (`integrator::Continuation`), since no next-event strategy reaches the light they pass.
    bsdf_windows: Portals,
    /// The polygons of `bsdf_windows` (primitive, vertices).
    bsdf_window_polygons: Vec<(u32, Vec<DVec3>)>,
    /// Plane mirrors (primitive, normal, reflectance), for virtual sources: listed once, not
    /// found by a scan of every primitive at every vertex.
    mirrors: Vec<(u32, DVec3, VirtualSourceReflectance)>,
    /// Some material treats shadow rays towards light sources apart (`illum`, `dielectric`):
    /// [`World::source_transmission`] then traces them crossing by crossing.
    source_crossings: bool,
    /// Volumes subtracted by `antimatter`, and what each primitive's modifier is.
    antimatter: Antimatter,
    /// The radiance-proportional distribution of escape directions, built on first use and
    /// dropped whenever the sources or the environment change.
    sky_distribution: std::sync::OnceLock<Option<SkyDistribution>>,
}

/// Radiance per direction of everything beyond the scene that no distant source covers.
pub type Environment = std::sync::Arc<dyn Fn(DVec3) -> DVec3 + Send + Sync>;

impl std::fmt::Debug for World {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("World")
            .field("primitives", &self.primitives.len())
            .field("bvh_nodes", &self.bvh.node_count())
            .field("distant_sources", &self.distant.len())
            .finish()
    }
}

impl World {
    /// Prepares a loaded scene for tracing, with the software box test.
    pub fn new(scene: &Scene) -> Result<Self, EngineError> {
        let mut world = Self::with_box_test(scene, Box::new(SlabTest))?;
        world.software_box_test = true;
        Ok(world)
    }

    /// As [`World::new`], with another box-test implementation (the FPGA unit).
    pub fn with_box_test(
        scene: &Scene,
        box_test: Box<dyn BoxTest + Send>,
    ) -> Result<Self, EngineError> {
        let mut primitives = Vec::new();
        let mut material_of = Vec::new();
        let mut materials = Vec::new();
        let mut material_index = std::collections::HashMap::new();
        let mut distant = Vec::new();
        let mut names = Vec::new();
        let mut polygon_vertices = Vec::new();
        let mut antimatter = Antimatter::default();
        let mut functions = FunctionLoader::default();
        for surface in scene.surfaces() {
            if let Shape::Source(source) = &surface.shape {
                let (material, patterns) = resolve(scene, surface.modifier)?;
                distant.extend(distant_emitter(surface, source, material, patterns)?);
                continue;
            }
            let key = surface.modifier;
            let index = match material_index.get(&key) {
                Some(&i) => i,
                None => {
                    let prepared = build::material_of(scene, key, surface, &mut functions)?;
                    materials.push(prepared);
                    let i = (materials.len() - 1) as u32;
                    material_index.insert(key, i);
                    i
                }
            };
            if let Shape::Polygon(p) = &surface.shape {
                polygon_vertices.push((primitives.len() as u32, p.vertices_m.clone()));
            }
            let subtracted = scene
                .material(surface.modifier)
                .and_then(|m| match &m.kind {
                    ModifierKind::Antimatter(a) => {
                        Some((surface.modifier, a.subtracted.as_slice()))
                    }
                    _ => None,
                });
            antimatter.push(surface.modifier, subtracted);
            names.push(surface.name.clone());
            primitives.push(match &surface.shape {
                Shape::Polygon(p) => Primitive::Polygon(PreparedPolygon::new(p)),
                Shape::Sphere(s) => Primitive::Sphere(s.clone()),
                Shape::Cylinder(c) => Primitive::Cone(PreparedCone::from_cylinder(c)),
                Shape::Cone(c) => Primitive::Cone(PreparedCone::from_cone(c)),
                Shape::Ring(r) => Primitive::Ring(r.clone()),
                Shape::Bubble(s) => Primitive::Inward(Box::new(Primitive::Sphere(s.clone()))),
                Shape::Tube(c) => {
                    Primitive::Inward(Box::new(Primitive::Cone(PreparedCone::from_cylinder(c))))
                }
                Shape::Cup(c) => {
                    Primitive::Inward(Box::new(Primitive::Cone(PreparedCone::from_cone(c))))
                }
                Shape::Source(_) => unreachable!("handled above"),
            });
            material_of.push(index);
        }
        let bounds: Vec<_> = primitives.iter().map(|p| p.bounds()).collect();
        let mut world = World {
            bvh: Bvh::build(&bounds),
            primitives,
            material_of,
            materials,
            box_test,
            software_box_test: false,
            bvh_unit: None,
            distant,
            environment: None,
            names,
            portal_candidates: Vec::new(),
            portals: Portals::default(),
            bsdf_windows: Portals::default(),
            bsdf_window_polygons: Vec::new(),
            mirrors: Vec::new(),
            source_crossings: false,
            antimatter,
            sky_distribution: std::sync::OnceLock::new(),
        };
        world.source_crossings = world.materials.iter().any(Material::has_source_crossing);
        world.mirrors = (0..world.primitives.len() as u32)
            .filter_map(|i| {
                let reflectance = world.material(i).virtual_source_reflectance()?;
                match &world.primitives[i as usize] {
                    Primitive::Polygon(p) => Some((i, p.normal, reflectance)),
                    _ => None,
                }
            })
            .collect();
        let bsdf_windows: Vec<(u32, Vec<DVec3>)> = polygon_vertices
            .iter()
            .filter(|(p, v)| {
                matches!(world.material(*p), Material::Bsdf(_)) && world.opens_to_outside(*p, v)
            })
            .cloned()
            .collect();
        world.bsdf_windows = Portals::new(&bsdf_windows);
        world.bsdf_window_polygons = bsdf_windows;
        world.portal_candidates = polygon_vertices
            .into_iter()
            .filter(|(p, _)| world.material(*p).is_clear())
            .collect();
        let found: Vec<(u32, Vec<DVec3>)> = world
            .portal_candidates
            .iter()
            .filter(|(p, v)| world.opens_to_outside(*p, v))
            .cloned()
            .collect();
        world.portals = Portals::new(&found);
        Ok(world)
    }

    /// Whether a glass, invisible or `BSDF` polygon is an opening to the outside: from its centre,
    /// on one side or the other, some of nine rays (the normal and eight at 60° from it)
    /// leave the scene without meeting anything opaque.
    fn opens_to_outside(&self, primitive: u32, vertices: &[DVec3]) -> bool {
        let Some(Primitive::Polygon(poly)) = self.primitives.get(primitive as usize) else {
            return false;
        };
        let centre = vertices.iter().copied().sum::<DVec3>() / vertices.len() as f64;
        let (u, v) = basis(poly.normal);
        for side in [1.0, -1.0] {
            let n = poly.normal * side;
            let mut dirs = vec![n];
            for k in 0..8 {
                let phi = k as f64 * std::f64::consts::FRAC_PI_4;
                dirs.push(
                    (n * 0.5 + (u * phi.cos() + v * phi.sin()) * 0.75_f64.sqrt()).normalize(),
                );
            }
            for d in dirs {
                if self.shadow_transmission(centre, Some(primitive), d) != DVec3::ZERO {
                    return true;
                }
            }
        }
        false
    }

    /// The portals next-event estimation samples the sky through (found automatically: glass
    /// and invisible polygons with a side open to the outside).
    pub fn portals(&self) -> &Portals {
        &self.portals
    }

    /// The `BSDF` windows open to the outside, as an area distribution (empty if none).
    pub fn bsdf_windows(&self) -> &Portals {
        &self.bsdf_windows
    }

    /// The polygons of [`World::bsdf_windows`]: (primitive, vertices).
    pub fn bsdf_window_polygons(&self) -> &[(u32, Vec<DVec3>)] {
        &self.bsdf_window_polygons
    }

    /// The plane's unit normal of a polygon primitive (None for other shapes).
    pub fn polygon_normal(&self, primitive: u32) -> Option<DVec3> {
        match self.primitives.get(primitive as usize)? {
            Primitive::Polygon(p) => Some(p.normal),
            _ => None,
        }
    }

    /// Adds openings (holes in the room's envelope, `super::openings` finds them) to the
    /// portals next-event estimation samples the sky through. A sampling aid only: results
    /// stay unbiased whatever is added.
    pub fn add_opening_portals(&mut self, openings: &[[DVec3; 4]]) {
        self.portals.add_openings(openings);
    }

    /// Names of the polygons used as portals.
    pub fn portal_names(&self) -> Vec<&str> {
        self.portals
            .primitives()
            .iter()
            .map(|&p| self.names[p as usize].as_str())
            .collect()
    }

    /// The portal polygons: (primitive index, surface name, vertices), in the portals'
    /// order. What the loop's glazing geometry (`validation::glazing`) is built from.
    pub fn portal_polygons(&self) -> Vec<(u32, &str, &[DVec3])> {
        self.portals
            .primitives()
            .iter()
            .filter_map(|&p| {
                let (_, v) = self.portal_candidates.iter().find(|(q, _)| *q == p)?;
                Some((p, self.names[p as usize].as_str(), v.as_slice()))
            })
            .collect()
    }

    /// Uses the named glass or invisible polygons as the portals instead of those found
    /// automatically (an empty list turns portal sampling off). A name that matches no such
    /// polygon is an error.
    pub fn set_portals(&mut self, names: &[&str]) -> Result<(), EngineError> {
        let mut chosen = Vec::new();
        for name in names {
            let matching: Vec<_> = self
                .portal_candidates
                .iter()
                .filter(|(p, _)| self.names[*p as usize] == *name)
                .cloned()
                .collect();
            if matching.is_empty() {
                return Err(EngineError::Setting {
                    name: "portal",
                    value: (*name).to_string(),
                    expected: "the name of a glass or invisible polygon in the scene",
                });
            }
            chosen.extend(matching);
        }
        self.portals = Portals::new(&chosen);
        Ok(())
    }

    /// Whether anything beyond the scene is bright: a `glow` distant source or an
    /// environment (the sun, a `light`, is reached by its own next-event estimation).
    pub fn has_escape_radiance(&self) -> bool {
        self.environment.is_some() || self.distant.iter().any(|s| s.kind == DistantKind::Glow)
    }

    /// The radiance-proportional distribution of escape directions (None if nothing beyond
    /// the scene is bright).
    pub fn sky_distribution(&self) -> Option<&SkyDistribution> {
        self.sky_distribution
            .get_or_init(|| {
                if self.has_escape_radiance() {
                    SkyDistribution::new(|d| self.escape_radiance(d))
                } else {
                    None
                }
            })
            .as_ref()
    }

    pub fn distant_sources(&self) -> &[DistantEmitter] {
        &self.distant
    }

    /// Adds a distant source (e.g. the sun extracted from a sky map, as a `light`).
    pub fn add_distant(&mut self, source: DistantEmitter) {
        self.sky_distribution = std::sync::OnceLock::new();
        self.distant.push(source);
    }

    /// Removes every distant source.
    pub fn clear_distant(&mut self) {
        self.sky_distribution = std::sync::OnceLock::new();
        self.distant.clear();
    }

    pub fn has_environment(&self) -> bool {
        self.environment.is_some()
    }

    /// Sets the radiance (W/sr/m² per RGB channel, RADIANCE units) of every direction that no
    /// distant source covers: a measured sky map, for instance. Distant sources take
    /// precedence, as a scene's `source`s are found first.
    pub fn set_environment(&mut self, environment: Option<Environment>) {
        self.sky_distribution = std::sync::OnceLock::new();
        self.environment = environment;
    }

    /// What a ray leaving the scene along unit `d` sees: a `glow` source containing it (a
    /// `light` is counted by next-event estimation only, RADIANCE source.c `badcomponent`),
    /// else the environment, else nothing.
    pub fn escape_radiance(&self, d: DVec3) -> DVec3 {
        match source_seen(&self.distant, d) {
            Some(s) if s.kind == DistantKind::Glow => s.radiance(d),
            Some(_) => DVec3::ZERO,
            None => self.environment.as_ref().map_or(DVec3::ZERO, |env| env(d)),
        }
    }

    /// The tree over the primitives (its shape sizes a ray unit; `engine::traversal_stats`).
    pub fn bvh(&self) -> &Bvh {
        &self.bvh
    }

    /// Traverses with the BVH ray unit behind `backend` from now on (the tree loaded into
    /// it); the answers stay the software traversal's, bit for bit (`engine::bvh_unit`).
    pub fn attach_bvh_unit(
        &mut self,
        backend: Box<dyn BvhUnitBackend>,
    ) -> Result<(), UnitTreeError> {
        self.bvh_unit = Some(BvhUnit::load(&self.bvh, &self.primitive_bounds(), backend)?);
        Ok(())
    }

    /// The attached BVH ray unit, with its counts.
    pub fn bvh_unit(&self) -> Option<&BvhUnit> {
        self.bvh_unit.as_ref()
    }

    /// Each primitive's box, as the tree is built over them.
    pub fn primitive_bounds(&self) -> Vec<super::slab::Aabb> {
        self.primitives.iter().map(|p| p.bounds()).collect()
    }

    /// The distance at which `ray` meets primitive `p` within `[t_min_m, t_max_m]`, if it does
    /// (the exact test a ray unit's candidate is finished with).
    pub fn primitive_distance_m(
        &self,
        p: u32,
        ray: &Ray,
        t_min_m: f64,
        t_max_m: f64,
    ) -> Option<f64> {
        self.primitives
            .get(p as usize)?
            .intersect(ray, t_min_m, t_max_m)
            .map(|h| h.t_m)
    }

    pub fn primitive_count(&self) -> usize {
        self.primitives.len()
    }

    pub fn material(&self, primitive: u32) -> &Material {
        &self.materials[self.material_of[primitive as usize] as usize]
    }

    /// The geometry of a primitive (virtual sources need the mirrors' planes).
    pub fn primitive(&self, primitive: u32) -> &Primitive {
        &self.primitives[primitive as usize]
    }

    /// Plane mirrors, the primitives that make virtual sources: (primitive, normal,
    /// reflectance).
    pub fn mirrors(&self) -> &[(u32, DVec3, VirtualSourceReflectance)] {
        &self.mirrors
    }

    pub fn is_flat(&self, primitive: u32) -> bool {
        self.primitives[primitive as usize].is_flat()
    }

    /// The closest surface along `ray`, not counting the flat surface `from` the ray leaves.
    pub fn intersect(&self, ray: &Ray, from: Option<u32>) -> Option<Hit> {
        self.closest_where(ray, from, |_| true)
    }

    /// Whether any surface (glass and invisible ones too) lies on `ray` nearer than
    /// `t_max_m`, not counting the flat surface `from`: whether a point that far along it is
    /// the ray's first hit. One unordered traversal that stops at the first surface found.
    pub fn blocked_within(&self, ray: &Ray, from: Option<u32>, t_max_m: f64) -> bool {
        if !self.antimatter.is_empty() {
            return self.intersect_within(ray, from, t_max_m).is_some();
        }
        let mut blocked = false;
        let mut visit = |p: u32| {
            let Some(t_min) = self.self_hit_t_min(p, from) else {
                return true;
            };
            blocked = self.primitives[p as usize]
                .intersect(ray, t_min, t_max_m)
                .is_some();
            !blocked
        };
        self.visit_crossed(ray, t_max_m, &mut visit);
        blocked
    }

    /// Every primitive whose box `ray` crosses nearer than `t_max_m`, in no order, handed to
    /// `visit` until it returns false ([`Bvh::visit_crossed`] with this world's box test).
    fn visit_crossed(&self, ray: &Ray, t_max_m: f64, visit: impl FnMut(u32) -> bool) {
        if let Some(unit) = &self.bvh_unit {
            unit.visit_crossed(&self.bvh, ray, 0.0, t_max_m, visit);
        } else if self.software_box_test {
            self.bvh.visit_crossed(&SlabTest, ray, 0.0, t_max_m, visit);
        } else {
            self.bvh
                .visit_crossed(self.box_test.as_ref(), ray, 0.0, t_max_m, visit);
        }
    }

    /// [`World::intersect`] nearer than `t_max_m`: a visibility test that need not look past
    /// the point it tests.
    pub fn intersect_within(&self, ray: &Ray, from: Option<u32>, t_max_m: f64) -> Option<Hit> {
        if !self.antimatter.is_empty() {
            return self.intersect(ray, from).filter(|h| h.t_m < t_max_m);
        }
        self.closest_raw_within(ray, from, t_max_m, |_| true)
    }

    /// The closest surface along `ray` (leaving `from`) that is neither glass nor invisible:
    /// one query where stepping through each pane took one per pane.
    pub fn first_opaque(&self, ray: &Ray, from: Option<u32>) -> Option<Hit> {
        self.closest_where(ray, from, |p| !self.material(p).is_clear())
    }

    /// The closest hit on a primitive `accept` takes, not counting the flat surface `from`,
    /// with antimatter applied: a surface inside a volume that subtracts it is passed, and a
    /// volume's own surface is met only where a ray leaves it into an object of its first
    /// modifier (m_clip.c), its normal turned around.
    fn closest_where(
        &self,
        ray: &Ray,
        from: Option<u32>,
        accept: impl Fn(u32) -> bool,
    ) -> Option<Hit> {
        if self.antimatter.is_empty() {
            return self.closest_raw(ray, from, accept);
        }
        let am = &self.antimatter;
        let (mut segment, mut from, mut travelled_m) = (*ray, from, 0.0);
        for _ in 0..MAX_SHADOW_CROSSINGS {
            let hit =
                self.closest_raw(&segment, from, |p| am.volume_of(p).is_some() || accept(p))?;
            let p = segment.at(hit.t_m);
            let d = segment.direction;
            let met = match am.volume_of(hit.primitive) {
                Some(v) => {
                    d.dot(hit.normal) > 0.0
                        && accept(hit.primitive)
                        && am.shaded_as(v).is_some_and(|m| {
                            self.is_inside(p, d, hit.primitive, |q| am.has_modifier(q, m))
                        })
                }
                None => !am
                    .subtracting(hit.primitive)
                    .any(|v| self.is_inside(p, d, hit.primitive, |q| am.volume_of(q) == Some(v))),
            };
            if met {
                let turned = am.volume_of(hit.primitive).is_some();
                return Some(Hit {
                    t_m: travelled_m + hit.t_m,
                    normal: if turned { -hit.normal } else { hit.normal },
                    primitive: hit.primitive,
                });
            }
            travelled_m += hit.t_m;
            segment = Ray::new(p, d);
            from = Some(hit.primitive);
        }
        None
    }

    /// Whether `p` (on primitive `from`) lies inside the closed surface made of the
    /// primitives `member` takes: the nearest of them along unit `d` is met from inside.
    fn is_inside(&self, p: DVec3, d: DVec3, from: u32, member: impl Fn(u32) -> bool) -> bool {
        self.closest_raw(&Ray::new(p, d), Some(from), member)
            .is_some_and(|h| d.dot(h.normal) > 0.0)
    }

    /// [`World::closest_where`] without antimatter.
    fn closest_raw(
        &self,
        ray: &Ray,
        from: Option<u32>,
        accept: impl Fn(u32) -> bool,
    ) -> Option<Hit> {
        self.closest_raw_within(ray, from, f64::INFINITY, accept)
    }

    /// [`World::closest_raw`] within `[0, t_max_m]`.
    fn closest_raw_within(
        &self,
        ray: &Ray,
        from: Option<u32>,
        t_max_m: f64,
        accept: impl Fn(u32) -> bool,
    ) -> Option<Hit> {
        let primitive_hit = |p: u32, t_max: f64| {
            if !accept(p) {
                return None;
            }
            let t_min = self.self_hit_t_min(p, from)?;
            self.primitives[p as usize]
                .intersect(ray, t_min, t_max)
                .map(|ShapeHit { t_m, normal }| Hit {
                    t_m,
                    normal,
                    primitive: p,
                })
        };
        if let Some(unit) = &self.bvh_unit {
            unit.closest(&self.bvh, ray, 0.0, t_max_m, primitive_hit, |h| h.t_m)
        } else if self.software_box_test {
            self.bvh
                .closest(&SlabTest, ray, 0.0, t_max_m, primitive_hit, |h| h.t_m)
        } else {
            self.bvh.closest(
                self.box_test.as_ref(),
                ray,
                0.0,
                t_max_m,
                primitive_hit,
                |h| h.t_m,
            )
        }
    }

    /// Nearest distance at which a ray leaving primitive `from` may hit primitive `p`: None
    /// for the flat surface it leaves, a small offset on the curved surface it leaves (whose
    /// far side it may still hit), 0 otherwise.
    fn self_hit_t_min(&self, p: u32, from: Option<u32>) -> Option<f64> {
        if Some(p) != from {
            Some(0.0)
        } else if self.is_flat(p) {
            None
        } else {
            Some(CURVED_SELF_HIT_M)
        }
    }

    /// What reaches `origin` from a distant source along unit `dir` through the scene: 1 if
    /// nothing is in the way, the product of the transmissions of `glass` and smooth `trans`
    /// surfaces crossed (RADIANCE traces shadow rays through them, glass.c and normal.c), 0 if
    /// anything else blocks it.
    ///
    /// One unordered traversal visits every surface the ray crosses (a product does not
    /// depend on the order) and stops at the first opaque one. A curved surface that
    /// transmits may be crossed twice, which one intersection per primitive cannot see, so a
    /// ray that meets one is traced crossing by crossing instead.
    pub fn shadow_transmission(&self, origin: DVec3, from: Option<u32>, dir: DVec3) -> DVec3 {
        self.transmission_within(origin, from, dir, f64::INFINITY)
            .transmission
    }

    /// [`World::shadow_transmission`] over the first `t_max_m` of the ray only, whether it
    /// crosses any surface there (invisible ones too), and where it was found blocked: what
    /// passes from a point to the surface it sees through glass.
    pub fn transmission_within(
        &self,
        origin: DVec3,
        from: Option<u32>,
        dir: DVec3,
        t_max_m: f64,
    ) -> ShadowSegment {
        if !self.antimatter.is_empty() {
            // Which surfaces count depends on the volumes crossed: in order only.
            return self.transmission_stepwise(origin, from, dir, t_max_m);
        }
        let ray = Ray::new(origin, dir);
        let mut t = DVec3::ONE;
        let mut crossed = false;
        let mut blocked_at_m = f64::INFINITY;
        let mut curved_crossing = false;
        let mut visit = |p: u32| {
            let Some(t_min) = self.self_hit_t_min(p, from) else {
                return true;
            };
            let Some(hit) = self.primitives[p as usize].intersect(&ray, t_min, t_max_m) else {
                return true;
            };
            crossed = true;
            let point = HitPoint {
                point_m: ray.at(hit.t_m),
                direction: dir,
                normal: hit.normal,
                distance_m: hit.t_m,
                flat: self.is_flat(p),
            };
            let factor = match self.material(p).shadow_crossing_at(&point) {
                ShadowCrossing::PassThrough => return true,
                ShadowCrossing::Transmits(factor) => factor,
                ShadowCrossing::Opaque => DVec3::ZERO,
            };
            if factor != DVec3::ZERO && !self.is_flat(p) {
                curved_crossing = true;
                return false;
            }
            t *= factor;
            if t == DVec3::ZERO {
                blocked_at_m = hit.t_m;
            }
            t != DVec3::ZERO
        };
        self.visit_crossed(&ray, t_max_m, &mut visit);
        if curved_crossing {
            self.transmission_stepwise(origin, from, dir, t_max_m)
        } else {
            ShadowSegment {
                transmission: t,
                crossed,
                blocked_at_m,
            }
        }
    }

    /// What reaches `origin` from a distant light source along unit `dir` (the sun's
    /// next-event estimate): as [`World::shadow_transmission`], except that an `illum` is its
    /// alternate material to such rays and a `dielectric` refracts them, as RADIANCE traces
    /// shadow rays (source.c `passillum`, dielectric.c). A ray that leaves the scene turned
    /// away from `dir` (a prism, a lens) misses the source: 0, where RADIANCE would still count
    /// a deflection within the source's own disc.
    pub fn source_transmission(&self, origin: DVec3, from: Option<u32>, dir: DVec3) -> DVec3 {
        if !self.source_crossings {
            return self.shadow_transmission(origin, from, dir);
        }
        let mut ray = Ray::new(origin, dir);
        let mut from = from;
        let mut t = DVec3::ONE;
        for _ in 0..MAX_SHADOW_CROSSINGS {
            let Some(hit) = self.intersect(&ray, from) else {
                let straight = ray.direction.dot(dir) >= 1.0 - 1e-12;
                return if straight { t } else { DVec3::ZERO };
            };
            let material = self.material(hit.primitive);
            t *= material.arrival_factor(ray.direction, hit.normal, hit.t_m, false);
            let flat = self.is_flat(hit.primitive);
            let next = match material.source_crossing(ray.direction, hit.normal, flat) {
                SourceCrossing::Straight(ShadowCrossing::PassThrough) => ray.direction,
                SourceCrossing::Straight(ShadowCrossing::Transmits(factor)) => {
                    t *= factor;
                    ray.direction
                }
                SourceCrossing::Straight(ShadowCrossing::Opaque) => return DVec3::ZERO,
                SourceCrossing::Refracts { direction, factor } => {
                    t *= factor;
                    direction
                }
            };
            if t == DVec3::ZERO {
                return t;
            }
            ray = Ray::new(ray.at(hit.t_m), next);
            from = Some(hit.primitive);
        }
        DVec3::ZERO
    }

    /// [`World::transmission_within`] crossing by crossing, one closest-hit query each.
    fn transmission_stepwise(
        &self,
        origin: DVec3,
        from: Option<u32>,
        dir: DVec3,
        t_max_m: f64,
    ) -> ShadowSegment {
        let mut ray = Ray::new(origin, dir);
        let mut from = from;
        let mut t = DVec3::ONE;
        let mut travelled_m = 0.0;
        let blocked = |at_m: f64| ShadowSegment {
            transmission: DVec3::ZERO,
            crossed: true,
            blocked_at_m: at_m,
        };
        for crossing in 0..MAX_SHADOW_CROSSINGS {
            let Some(hit) = self
                .intersect(&ray, from)
                .filter(|h| travelled_m + h.t_m < t_max_m)
            else {
                return ShadowSegment {
                    transmission: t,
                    crossed: crossing > 0,
                    blocked_at_m: f64::INFINITY,
                };
            };
            travelled_m += hit.t_m;
            let flat = self.is_flat(hit.primitive);
            let point = hit.as_seen(ray.at(hit.t_m), dir, flat);
            match self.material(hit.primitive).shadow_crossing_at(&point) {
                ShadowCrossing::PassThrough => {}
                ShadowCrossing::Transmits(factor) => t *= factor,
                ShadowCrossing::Opaque => return blocked(travelled_m),
            }
            if t == DVec3::ZERO {
                return blocked(travelled_m);
            }
            ray = Ray::new(ray.at(hit.t_m), dir);
            from = Some(hit.primitive);
        }
        blocked(travelled_m)
    }
}

/// What a shadow ray meets over a stretch of its line ([`World::transmission_within`]).
#[derive(Clone, Copy, Debug)]
pub struct ShadowSegment {
    /// The product of the transmissions crossed; 0 if something opaque is in the way.
    pub transmission: DVec3,
    /// Some surface (glass, invisible or opaque) lies on the stretch.
    pub crossed: bool,
    /// Where the surface that stopped the ray lies (infinite if none did). Found by an
    /// unordered traversal, it is a blocker, not always the nearest one.
    pub blocked_at_m: f64,
}

/// The distant emitter of a `source` surface `s` with its material `material` and the
/// patterns on its chain; None if it is `void` or never illuminates.
fn distant_emitter(
    surface: &Surface,
    s: &DistantSource,
    material: Option<&Modifier>,
    patterns: Vec<SkyFunction>,
) -> Result<Option<DistantEmitter>, EngineError> {
    let Some(m) = material else {
        return Ok(None); // void: RADIANCE ignores it
    };
    let (kind, radiance, illuminates) = match &m.kind {
        ModifierKind::Light(l) => (DistantKind::Light, l.radiance_w_sr_m2, true),
        ModifierKind::Glow(g) => (
            DistantKind::Glow,
            g.radiance_w_sr_m2,
            Emitter::glow_illuminates(g.max_radius_m),
        ),
        other => {
            return Err(EngineError::Unsupported {
                at: surface.origin.clone(),
                what: format!(
                    "source `{}` has a {} material; only light and glow are traced \
                     on a distant source",
                    surface.name,
                    other.type_name()
                ),
            })
        }
    };
    if !illuminates {
        return Ok(None);
    }
    let half = 0.5 * s.angle_deg.to_radians();
    Ok(Some(DistantEmitter {
        name: surface.name.clone(),
        kind,
        direction: s.direction,
        cos_half_angle: half.cos(),
        solid_angle_sr: s.solid_angle_sr(),
        radiance_w_sr_m2: radiance,
        patterns,
    }))
}
