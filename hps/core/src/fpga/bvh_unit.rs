//! The BVH ray unit's backends (issue 22 item 4; formats and golden model in
//! `skylux_regmap::bvh_format`): the node memory loaded once per room, then one ray's words
//! in and its candidates out.
//!
//! [`BvhUnitBackend`] is what the engine's unit traversal (`engine::bvh_unit`) calls; the
//! golden model ([`GoldenBvhUnit`]) answers bit for bit as the unit does.

use skylux_regmap::bvh_format::{
    pack_candidate, pack_end, result_tag, traverse_counting, Order, UnitNode, MAX_NODES,
    NODE_WORDS, RAY_WORDS, RESULT_END_BIT,
};
use std::sync::atomic::{AtomicU64, Ordering};

/// One node's memory words.
pub type NodeWords = [u64; NODE_WORDS];
/// One ray's words.
pub type RayWords = [u64; RAY_WORDS];

/// Why the unit could not be loaded or did not answer. Every variant names what is concerned.
#[derive(Debug, thiserror::Error, PartialEq, Eq)]
pub enum BvhUnitError {
    #[error("node {index} of the BVH unit's memory has a wrong magic byte")]
    BadNode { index: usize },
    #[error("{nodes} nodes do not fit the BVH unit's memory of {MAX_NODES}")]
    TooManyNodes { nodes: usize },
    #[error("the BVH unit holds no tree (bvh.node_count is 0)")]
    Empty,
    #[error("the BVH unit's answer for a ray ended without its end word ({words} words)")]
    NoEnd { words: usize },
    #[error("the BVH unit's end word counts {counted} candidates, {written} were written")]
    CountMismatch { counted: u32, written: usize },
    #[error("a BVH unit result word carries tag {found}, its ray's end word {expected}")]
    TagMismatch { found: u8, expected: u8 },
    #[error("BVH unit fault: {0}")]
    Fault(String),
}

/// Traverses rays on a loaded tree.
pub trait BvhUnitBackend: Send + Sync {
    /// Loads the node memory (node 0 first).
    fn load(&mut self, nodes: &[NodeWords]) -> Result<(), BvhUnitError>;
    /// Appends the unit's result words for one ray (its candidates, then its end word; for a
    /// refused ray the candidates found before the refusal, which the caller ignores).
    fn traverse(
        &self,
        order: Order,
        ray: &RayWords,
        results: &mut Vec<u64>,
    ) -> Result<(), BvhUnitError>;
}

/// The golden model as a backend. It answers each ray alone, as a unit that was idle before
/// the ray (`bvh_format`'s tag rule), so every word carries tag 0.
#[derive(Debug, Default)]
pub struct GoldenBvhUnit {
    nodes: Vec<UnitNode>,
    /// Node visits (pair tests) over every ray traversed: the unit's work.
    pub node_visits: AtomicU64,
}

impl BvhUnitBackend for GoldenBvhUnit {
    fn load(&mut self, nodes: &[NodeWords]) -> Result<(), BvhUnitError> {
        if nodes.is_empty() {
            return Err(BvhUnitError::Empty);
        }
        if nodes.len() > MAX_NODES {
            return Err(BvhUnitError::TooManyNodes { nodes: nodes.len() });
        }
        self.nodes = nodes
            .iter()
            .enumerate()
            .map(|(index, w)| UnitNode::unpack(w).ok_or(BvhUnitError::BadNode { index }))
            .collect::<Result<_, _>>()?;
        Ok(())
    }

    fn traverse(
        &self,
        order: Order,
        ray: &RayWords,
        results: &mut Vec<u64>,
    ) -> Result<(), BvhUnitError> {
        if self.nodes.is_empty() {
            return Err(BvhUnitError::Empty);
        }
        let mut visits = 0;
        let (candidates, refusal) = traverse_counting(&self.nodes, ray, order, &mut visits);
        results.extend(candidates.iter().map(|&c| pack_candidate(c, GOLDEN_TAG)));
        results.push(pack_end(candidates.len() as u32, refusal, GOLDEN_TAG));
        self.node_visits.fetch_add(visits as u64, Ordering::Relaxed);
        Ok(())
    }
}

/// The tag of every word the golden backend writes (it answers one ray after an idle unit).
pub const GOLDEN_TAG: u8 = 0;

/// Checks that `words` is one ray's complete answer: candidates, then an end word counting
/// them (refused or not), all with the end word's tag. Returns the end word.
pub fn check_answer(words: &[u64]) -> Result<u64, BvhUnitError> {
    let Some((&end, candidates)) = words.split_last() else {
        return Err(BvhUnitError::NoEnd { words: 0 });
    };
    let is_end = |w: u64| w >> RESULT_END_BIT == 1;
    if !is_end(end) || candidates.iter().any(|&w| is_end(w)) {
        return Err(BvhUnitError::NoEnd { words: words.len() });
    }
    let expected = result_tag(end);
    if let Some(&w) = candidates.iter().find(|&&w| result_tag(w) != expected) {
        return Err(BvhUnitError::TagMismatch {
            found: result_tag(w),
            expected,
        });
    }
    let counted = end as u32;
    if counted as usize != candidates.len() {
        return Err(BvhUnitError::CountMismatch {
            counted,
            written: candidates.len(),
        });
    }
    Ok(end)
}

#[cfg(test)]
mod tests {
    use super::*;
    use skylux_regmap::bvh_format::{Candidate, Refusal};

    #[test]
    fn load_refuses_bad_memories() {
        let mut g = GoldenBvhUnit::default();
        assert_eq!(g.load(&[]), Err(BvhUnitError::Empty));
        let good = UnitNode::default().pack();
        let mut bad = good;
        bad[4] = 0;
        assert_eq!(
            g.load(&[good, bad]),
            Err(BvhUnitError::BadNode { index: 1 })
        );
        assert_eq!(
            g.load(&vec![good; MAX_NODES + 1]),
            Err(BvhUnitError::TooManyNodes {
                nodes: MAX_NODES + 1
            })
        );
        let mut out = vec![];
        assert_eq!(
            GoldenBvhUnit::default().traverse(Order::NearFirst, &[0; RAY_WORDS], &mut out),
            Err(BvhUnitError::Empty)
        );
    }

    #[test]
    fn answers_are_checked() {
        let c = pack_candidate(Candidate { leaf: 3, t_near: 9 }, 5);
        assert!(check_answer(&[c, pack_end(1, None, 5)]).is_ok());
        // A refused ray's end word counts the candidates written before the refusal.
        let refused = pack_end(1, Some(Refusal::Runaway), 5);
        assert_eq!(check_answer(&[c, refused]), Ok(refused));
        assert_eq!(
            check_answer(&[c, c, pack_end(1, None, 5)]),
            Err(BvhUnitError::CountMismatch {
                counted: 1,
                written: 2
            })
        );
        assert_eq!(
            check_answer(&[pack_end(0, Some(Refusal::StackOverflow), 5)]).map(|_| ()),
            Ok(())
        );
        assert_eq!(
            check_answer(&[c, pack_end(1, None, 6)]),
            Err(BvhUnitError::TagMismatch {
                found: 5,
                expected: 6
            })
        );
        assert_eq!(check_answer(&[c]), Err(BvhUnitError::NoEnd { words: 1 }));
        assert_eq!(check_answer(&[]), Err(BvhUnitError::NoEnd { words: 0 }));
    }

    proptest::proptest! {
        /// Whatever words a faulty unit writes, the check answers without a panic, and what it
        /// accepts is one ray's answer: one end word, last, counting the words before it, all
        /// of one tag.
        #[test]
        fn any_words_are_checked_without_panic(
            words in proptest::collection::vec(proptest::prelude::any::<u64>(), 0..12),
            end_last in proptest::prelude::any::<bool>(),
        ) {
            let mut words = words;
            if end_last && !words.is_empty() {
                let n = words.len() as u64 - 1;
                let last = words.len() - 1;
                words[last] = (words[last] & !0xFFFF_FFFF) | n | (1 << RESULT_END_BIT);
            }
            if let Ok(end) = check_answer(&words) {
                proptest::prop_assert_eq!(Some(&end), words.last());
                proptest::prop_assert_eq!(end as u32 as usize, words.len() - 1);
                proptest::prop_assert!(words.iter().all(|&w| result_tag(w) == result_tag(end)));
                proptest::prop_assert_eq!(
                    words.iter().filter(|&&w| w >> RESULT_END_BIT == 1).count(),
                    1
                );
            }
        }
    }
}
