use super::*;

#[test]
fn the_first_doubt_met_is_the_reason_and_each_is_kept_once() {
    let mut doubts = Doubts::none();
    assert_eq!(doubts.reason(), None);
    doubts.add(Doubt::RootCluster);
    doubts.add(Doubt::NearCusp);
    doubts.add(Doubt::RootCluster);
    assert_eq!(doubts.iter().count(), 2);
    assert_eq!(
        doubts.reason().as_deref(),
        Some("roots within rounding of each other (a double root or a cluster)")
    );
}

#[test]
fn and_then_carries_the_earlier_doubts_first() {
    let first = Certified::with(2, Doubt::SearchLimit);
    let both = first.and_then(|x| Certified::with(x * 3, Doubt::Junction));
    assert_eq!(both.value, 6);
    let order: Vec<_> = both.doubts.iter().cloned().collect();
    assert_eq!(order, [Doubt::SearchLimit, Doubt::Junction]);
    let proven = Certified::proven(1).map(|x| x + 1);
    assert!(proven.is_certified() && proven.value == 2);
}

#[test]
fn reasons_with_a_place_name_it() {
    let corner = UnreachedCorner {
        at: [1.5, -2.0],
        boundary: 1,
        turn: 0.25,
        more: 2,
    };
    let text = Doubt::Coverage {
        unreached: Some(corner),
    }
    .to_string();
    assert_eq!(
        text,
        "the feet of the edges do not cover the boundaries once round: a piece of the axis \
         may be missing: no leaf reaches the convex corner at (1.5, -2) of boundary 1, \
         which turns by 2.5e-1 rad (and 2 more such corners)"
    );
    assert_eq!(
        Doubt::AxisGraph { unreached: None }.to_string(),
        "the graph is not one connected piece with one cycle per hole"
    );
    assert_eq!(
        Doubt::CurvatureAtJoint { u: 2.5 }.to_string(),
        "the curvature vanishes within rounding at the smooth joint at u = 2.5"
    );
}

#[test]
fn every_reason_is_stated() {
    let all = [
        Doubt::NoExactForm,
        Doubt::CertificationOff,
        Doubt::ExactFormPrecision { degree: 4 },
        Doubt::SimplicityUndecided,
        Doubt::NearCusp,
        Doubt::OddInflections,
        Doubt::CurvatureUnresolved,
        Doubt::CornerUndecided,
        Doubt::RootsUnresolved,
        Doubt::FlatWithinRounding,
        Doubt::CornerInStraight,
        Doubt::Continuum,
        Doubt::RootCluster,
        Doubt::RootAtEnd,
        Doubt::NormalJump,
        Doubt::NotAPair,
        Doubt::SectionUndecided,
        Doubt::EpsilonCut,
        Doubt::ConstantWidth,
        Doubt::CurvesTouch,
        Doubt::TangentTestsDisagree,
        Doubt::CurvatureAtSegmentEnd { u: 1.0, segment: 0 },
        Doubt::CurvatureAtJoint { u: 1.0 },
        Doubt::TangencyFromCorner { u: 1.0, segment: 2 },
        Doubt::FootFromCorner { u: 1.0, segment: 2 },
        Doubt::FootFromJoint { u: 1.0, segment: 2 },
        Doubt::TangencyFromJoint { u: 1.0, segment: 2 },
        Doubt::CornerFeetNotFound {
            segment: 1,
            why: "no root".into(),
        },
        Doubt::DiskByNearest,
        Doubt::Junction,
        Doubt::AxisEnd,
        Doubt::CornerLeaf,
        Doubt::AxisGraph { unreached: None },
        Doubt::Coverage { unreached: None },
        Doubt::SearchLimit,
        Doubt::Cancelled,
        Doubt::AxisUncertified,
        Doubt::SeamUnconverged,
        Doubt::LoopLeftOut,
        Doubt::LoopBridged,
        Doubt::OffsetError { error: 0.5 },
        Doubt::LoopNotAProfile {
            why: "it crosses itself".into(),
        },
        Doubt::NeckUnresolved,
        Doubt::LoopsCross,
        Doubt::UnreadOutline {
            names: vec!["SOLID 5D".into(), "HATCH 7A".into()],
        },
        Doubt::InPart {
            part: 1,
            doubt: Box::new(Doubt::SearchLimit),
        },
        Doubt::Stated {
            reason: "as a document stated it".into(),
        },
    ];
    let texts: std::collections::HashSet<String> = all.iter().map(|d| d.to_string()).collect();
    assert_eq!(texts.len(), all.len(), "two doubts share a reason");
    assert!(texts.iter().all(|t| t.len() > 10 && !t.ends_with('.')));
}
