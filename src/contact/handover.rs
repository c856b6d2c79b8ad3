//! A host's hand-overs checked against each other (see [`bodies::HostSystem`]): each contact
//! pair's section (the analysis kind and thickness of its A side), its nodes' radii in
//! axisymmetry, and the elements along A (their materials against their pair's section). A
//! mismatch would not fail later, it would give wrong numbers: stresses recovered with a
//! plane-strain material on an axisymmetric pair miss the hoop strain `u_r / r`.
//!
//! The C API calls these where each part is handed over (`hycon_host_add_pair`,
//! `hycon_host_set_elements`), and [`ContactAnalysis::host`] calls them all again, so a Rust
//! caller gets the same errors.
//!
//! [`bodies::HostSystem`]: super::bodies::HostSystem
//! [`ContactAnalysis::host`]: super::iteration::ContactAnalysis::host

use super::bodies::HostElements;
use super::iteration::{ContactPair, in_pair};
use super::plane::mortar::{self, SurfaceMeasure};
use crate::error::{Error, Result};
use crate::material::{Analysis, Material};
use std::collections::HashMap;

/// How far (relative) an element's thickness may differ from its pair's: round-off of the
/// host's two copies of one value, not another thickness.
const THICKNESS_TOLERANCE: f64 = 1e-12;

/// The A side of a host pair as the contact integrals and the stress recovery see it: the
/// analysis kind of its elements and their thickness (1 in axisymmetry). All pairs of a host
/// share one kind.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Section {
    /// Plane strain, plane stress or axisymmetric.
    pub analysis: Analysis,
    /// The elements' thickness `t` (plane), or 1 (axisymmetric: the measure is `2 pi r`).
    pub thickness: f64,
}

impl Section {
    /// A checked section: a plane thickness finite, positive and within range, an axisymmetric
    /// one exactly 1 (see [`SurfaceMeasure::new`]).
    ///
    /// # Errors
    /// [`Error::InvalidInput`] saying what is wrong.
    pub fn new(analysis: Analysis, thickness: f64) -> Result<Self> {
        SurfaceMeasure::new(analysis, thickness)?;
        Ok(Section {
            analysis,
            thickness,
        })
    }

    /// The section of elements made of `material`.
    pub fn of(material: &Material) -> Self {
        Section {
            analysis: material.analysis,
            thickness: material.thickness,
        }
    }

    /// The measure that weights the pair's contact integrals: `t`, or `2 pi r`.
    ///
    /// # Errors
    /// As [`new`](Self::new), for a section built field by field.
    pub fn measure(&self) -> Result<SurfaceMeasure> {
        SurfaceMeasure::new(self.analysis, self.thickness)
    }

    /// Whether elements of `material` are of this section: the same kind and the same
    /// thickness (to `THICKNESS_TOLERANCE`, 1e-12 relative).
    fn holds(&self, material: &Material) -> bool {
        let (t, s) = (material.thickness, self.thickness);
        material.analysis == self.analysis && (t - s).abs() <= THICKNESS_TOLERANCE * t.max(s)
    }
}

/// One valid section per pair, all of one analysis kind (plane strain, plane stress or
/// axisymmetric: hycon's model API rejects a mix in one model too).
///
/// # Errors
/// [`Error::InvalidInput`] naming the pair.
pub fn check_sections(sections: &[Section], pairs: usize) -> Result<()> {
    if sections.len() != pairs {
        return Err(Error::InvalidInput(format!(
            "{} sections for {pairs} contact pairs (one per pair)",
            sections.len()
        )));
    }
    for (i, s) in sections.iter().enumerate() {
        s.measure().map_err(|e| in_pair(i, e))?;
        let first = sections[0].analysis;
        if s.analysis != first {
            return Err(in_pair(
                i,
                Error::InvalidInput(format!(
                    "its analysis ({}) is not pair 0's ({}): all pairs of a host share one \
                     analysis kind",
                    s.analysis.name(),
                    first.name()
                )),
            ));
        }
    }
    Ok(())
}

/// In axisymmetry, every node of a polyline (`ids`, at `points` in the same order, 2 values
/// `r, z` per node; `side` names it) at `r = x >= 0`, within round-off of its segments' length (the rule of
/// [`mortar::evaluate`] for A's nodes); nothing to check in plane analysis.
///
/// # Errors
/// [`Error::InvalidInput`] naming the node.
pub fn check_radii(section: &Section, side: &str, ids: &[usize], points: &[f64]) -> Result<()> {
    if section.analysis != Analysis::Axisymmetric {
        return Ok(());
    }
    let points = points.as_chunks::<2>().0;
    let order: Vec<usize> = (0..points.len()).collect();
    match mortar::below_axis(&order, points) {
        None => Ok(()),
        Some(k) => Err(Error::InvalidInput(format!(
            "{side} node {} has r = x = {} < 0 (axisymmetric: x is the radius)",
            ids[k], points[k][0]
        ))),
    }
}

/// The elements a host hands over against its pairs: every material the elements use of the
/// pairs' analysis kind, and every element on a segment of a pair's A polyline (either way
/// round) of that pair's [`Section`] (kind and thickness). Indices out of range are skipped:
/// the elements' own check ([`check_elements`](super::bodies::check_elements)) reports them.
/// Nothing to check before the first pair.
///
/// # Errors
/// [`Error::InvalidInput`] naming the element, its material and the pair.
pub fn check_element_sections(
    elements: &HostElements,
    pairs: &[ContactPair],
    sections: &[Section],
) -> Result<()> {
    let Some(first) = sections.first() else {
        return Ok(());
    };
    let used = |m: &usize| elements.materials.get(*m).map(|mat| (*m, mat));
    if let Some((m, material)) = elements
        .element_material
        .iter()
        .filter_map(used)
        .find(|(_, mat)| mat.analysis != first.analysis)
    {
        return Err(Error::InvalidInput(format!(
            "element material {m} is {}, the contact pairs are {}: the element stresses would \
             be of another analysis",
            material.analysis.name(),
            first.analysis.name()
        )));
    }
    let segments = a_segments(pairs);
    for (e, ids) in elements.offsets.windows(2).enumerate() {
        let (Some(nodes), Some((m, material))) = (
            elements.nodes.get(ids[0]..ids[1]),
            elements.element_material.get(e).and_then(used),
        ) else {
            continue;
        };
        for i in 0..nodes.len() {
            let edge = undirected(nodes[i], nodes[(i + 1) % nodes.len()]);
            let on = segments.get(&edge).map_or(&[][..], Vec::as_slice);
            if let Some(&p) = on.iter().find(|&&p| !sections[p].holds(material)) {
                let section = sections[p];
                return Err(Error::InvalidInput(format!(
                    "element {e} (on A segment {} -> {} of contact pair {p}) has material {m} \
                     ({}, thickness {}), the pair is {} with thickness {}: an element along A \
                     has its pair's analysis and thickness",
                    edge.0,
                    edge.1,
                    material.analysis.name(),
                    material.thickness,
                    section.analysis.name(),
                    section.thickness
                )));
            }
        }
    }
    Ok(())
}

/// The segments of the pairs' A polylines (node ids, smaller first) and the pairs of each.
fn a_segments(pairs: &[ContactPair]) -> HashMap<(usize, usize), Vec<usize>> {
    let mut segments: HashMap<(usize, usize), Vec<usize>> = HashMap::new();
    for (p, pair) in pairs.iter().enumerate() {
        for w in pair.a.windows(2) {
            segments.entry(undirected(w[0], w[1])).or_default().push(p);
        }
    }
    segments
}

fn undirected(p: usize, q: usize) -> (usize, usize) {
    (p.min(q), p.max(q))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contact::bodies::HostNode;
    use crate::contact::space::Vector;
    use crate::element::Formulation;

    fn section(analysis: Analysis, thickness: f64) -> Section {
        Section::new(analysis, thickness).unwrap()
    }

    /// One analysis kind per host, plane strain and plane stress included; thicknesses may
    /// differ between pairs; each section valid.
    #[test]
    fn sections_share_one_kind() {
        let strain = section(Analysis::PlaneStrain, 1.0);
        let stress = section(Analysis::PlaneStress, 1.0);
        check_sections(&[strain, section(Analysis::PlaneStrain, 2.0)], 2).unwrap();
        let e = check_sections(&[strain, stress], 2)
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("contact pair 1") && e.contains("one analysis kind"),
            "{e}"
        );
        let axi = section(Analysis::Axisymmetric, 1.0);
        let e = check_sections(&[axi, strain], 2).unwrap_err().to_string();
        assert!(e.contains("contact pair 1"), "{e}");
        let e = check_sections(&[strain], 2).unwrap_err().to_string();
        assert!(e.contains("1 sections for 2 contact pairs"), "{e}");
        let bad = Section {
            analysis: Analysis::PlaneStress,
            thickness: -1.0,
        };
        let e = check_sections(&[bad], 1).unwrap_err().to_string();
        assert!(e.contains("thickness"), "{e}");
        let e = Section::new(Analysis::Axisymmetric, 2.0).unwrap_err();
        assert!(e.to_string().contains("2 pi r"), "{e}");
    }

    /// In axisymmetry a node at r < 0 beyond round-off (1e-10 of its segments) is named; on
    /// the axis (to round-off) it is fine; plane analysis has no axis.
    #[test]
    fn radii_are_not_negative_in_axisymmetry() {
        let axi = section(Analysis::Axisymmetric, 1.0);
        let ids = [7, 8, 9];
        check_radii(&axi, "A", &ids, &[-1e-12, 0.0, 1.0, 0.0, 2.0, 0.0]).unwrap();
        let points = [0.0, 0.0, -0.5, 1.0, 0.0, 2.0];
        let e = check_radii(&axi, "B", &ids, &points)
            .unwrap_err()
            .to_string();
        assert!(e.contains("B node 8") && e.contains("r = x = -0.5"), "{e}");
        check_radii(&section(Analysis::PlaneStrain, 1.0), "B", &ids, &points).unwrap();
    }

    /// Two unit squares on the A polyline 1 -> 0 (ids 0..6 as in the mesh below), each of its
    /// material: a mismatch of kind or thickness of an element on A is named, one off A only
    /// for its kind.
    #[test]
    fn elements_have_their_pairs_section() {
        let node = |id: usize, position: Vector| HostNode {
            id,
            position,
            equations: [None, None].into(),
        };
        let elements = |materials: Vec<Material>| HostElements {
            formulation: Formulation::Hybrid,
            materials,
            element_material: vec![0, 1],
            offsets: vec![0, 4, 8],
            nodes: vec![0, 1, 4, 5, 1, 2, 3, 4],
            node_table: vec![
                node(0, Vector::plane(0.0, 0.0)),
                node(1, Vector::plane(1.0, 0.0)),
                node(2, Vector::plane(2.0, 0.0)),
                node(3, Vector::plane(2.0, 1.0)),
                node(4, Vector::plane(1.0, 1.0)),
                node(5, Vector::plane(0.0, 1.0)),
            ],
        };
        let material = |t: f64, a: Analysis| Material::new(1.0, 0.3, t, a).unwrap();
        let pair = ContactPair {
            a: vec![1, 0],
            b: vec![10, 11],
            friction: 0.0,
        };
        let pairs = [pair];
        let strain = |t: f64| material(t, Analysis::PlaneStrain);
        let at = |t: f64| [section(Analysis::PlaneStrain, t)];
        // the element off A may have another thickness
        check_element_sections(&elements(vec![strain(2.0), strain(3.0)]), &pairs, &at(2.0))
            .unwrap();
        check_element_sections(&elements(vec![strain(2.0)]), &pairs, &[]).unwrap();
        let e = check_element_sections(&elements(vec![strain(2.0), strain(3.0)]), &pairs, &at(3.0))
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("element 0") && e.contains("thickness 2") && e.contains("thickness 3"),
            "{e}"
        );
        let stress = material(2.0, Analysis::PlaneStress);
        let e = check_element_sections(&elements(vec![stress, stress]), &pairs, &at(2.0))
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("plane stress") && e.contains("plane strain"),
            "{e}"
        );
        let axi = [section(Analysis::Axisymmetric, 1.0)];
        let e = check_element_sections(&elements(vec![strain(1.0), strain(1.0)]), &pairs, &axi)
            .unwrap_err()
            .to_string();
        assert!(e.contains("axisymmetric"), "{e}");
    }
}
