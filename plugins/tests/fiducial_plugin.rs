//! The fiducial plugin fed a scan: one tagged, labelled marker per detection.

mod support;

use framework::PluginConfig;
use framework::config::{DeviceRef, Param};
use player_proto::interfaces::common::Pose3d;
use player_proto::interfaces::fiducial::{Fiducial, FiducialData, FiducialItem};
use player_proto::message::Message;
use player_proto::{DevAddr, MsgType};
use support::harness;

#[test]
fn detections_become_tagged_markers() {
    let mut tag = Param::new("tag", "person");
    tag.attributes.push(("id".into(), "7".into()));
    let config = PluginConfig {
        library: "libpv3d_fiducial".into(),
        id: "f".into(),
        device: Some(DeviceRef {
            host: "h".into(),
            port: 6665,
            addr: "fiducial:0".parse().unwrap(),
            driver: "stage".into(),
        }),
        params: vec![tag],
        ..PluginConfig::default()
    };
    let mut h = harness();
    let mut plugin = h.make(config).unwrap();
    let item = |id, px| FiducialItem {
        id,
        pose: Pose3d {
            px,
            ..Pose3d::default()
        },
        upose: Pose3d::default(),
    };
    let scan = FiducialData {
        fiducials: vec![item(7, 2.0), item(0, 6.0)],
    };
    let addr: DevAddr = "fiducial:0".parse().unwrap();
    h.device
        .push(Message::typed(addr, MsgType::Data, Fiducial::Scan(scan)));
    assert!(h.run_changes_scene(plugin.as_mut()));
    let scene = &h.scene;
    let markers: Vec<_> = scene
        .iter()
        .filter(|(_, o)| o.has_tag("fiducial"))
        .collect();
    assert_eq!(markers.len(), 2);
    let person = markers.iter().find(|(_, o)| o.has_tag("id:7")).unwrap();
    assert!(person.1.has_tag("person"));
    assert_eq!(person.1.geometry.labels[0].text, "#7");
    let at = scene
        .world_transform(person.0)
        .transform_point3(glam::Vec3::ZERO);
    assert!((at.x - 2.0).abs() < 1e-6);
}
