//! A recording as a rosbag2 folder — `metadata.yaml` and one MCAP file whose schemas are
//! `ros2msg` definitions and whose messages are CDR — that `ros2 bag play`, `ros2 bag info`,
//! rosbags and Foxglove read. Each robot connection of the recording is a namespace (its name
//! where the caller knows one, else `HOST_PORT`); its messages go through [`convert`], the
//! same conversion as the live front's.

use std::collections::{BTreeMap, HashMap};
use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};

use mcap::records::MessageHeader;
use player_proto::RobotId;
use player_proto::capture::Direction;
use player_proto::message::Message;
use player_proto::recording::{Event, Record};

use crate::cdr::CdrError;
use crate::convert::Converted;
use crate::converter::Converter;
use crate::names::namespace;

/// Why a rosbag2 folder could not be written.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum BagError {
    #[error("{path}: {source}")]
    Io {
        path: String,
        source: std::io::Error,
    },
    #[error("{path} exists: a rosbag2 folder is written anew")]
    Exists { path: String },
    #[error("writing {path}: {source}")]
    Mcap {
        path: String,
        source: mcap::McapError,
    },
    #[error(transparent)]
    Cdr(#[from] CdrError),
}

/// What a bag holds, when written.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct BagStats {
    /// Messages by topic.
    pub topics: BTreeMap<String, u64>,
    /// Player messages with no ROS 2 counterpart (yet), by interface and subtype.
    pub unmapped: u64,
    /// Messages whose body did not decode.
    pub undecodable: u64,
}

/// How a topic is offered, as rosbag2 keeps it (`offered_qos_profiles`): sensor data best
/// effort, the rest reliable; `/tf_static` and maps transient local.
fn qos(topic: &str) -> String {
    let sensor = ["scan", "image_raw", "camera_info", "sonar", "range"];
    let best_effort = sensor
        .iter()
        .any(|kind| topic.ends_with(&format!("/{kind}")) || topic.contains(&format!("/{kind}_")))
        || topic.contains("/image_raw");
    let latched = topic == "/tf_static"
        || topic == "/map"
        || topic.starts_with("/map_")
        || topic.ends_with("/plan")
        || topic.contains("/plan_");
    let forever = "\n    sec: 2147483647\n    nsec: 4294967295";
    format!(
        "- history: 1\n  depth: 10\n  reliability: {}\n  durability: {}\n  deadline:{forever}\n  lifespan:{forever}\n  liveliness: 1\n  liveliness_lease_duration:{forever}\n  avoid_ros_namespace_conventions: false",
        if best_effort { 2 } else { 1 },
        if latched { 1 } else { 2 },
    )
}

/// Writes a rosbag2 folder at `folder` from `records`; `names` gives robot names by
/// (host, port) where known.
pub struct BagWriter {
    folder: PathBuf,
    file_name: String,
    out: mcap::Writer<BufWriter<File>>,
    schemas: HashMap<&'static str, u16>,
    channels: HashMap<String, (u16, &'static str)>,
    /// Each connection's robot, as its conversion.
    connections: HashMap<u32, Converter>,
    names: HashMap<(String, u16), String>,
    stats: BagStats,
    sequence: u32,
    first_ns: Option<u64>,
    last_ns: u64,
}

impl BagWriter {
    /// Starts the folder (which must not exist) and its MCAP file.
    pub fn create(folder: &Path, names: &[RobotId]) -> Result<BagWriter, BagError> {
        let path = |p: &Path| p.display().to_string();
        if folder.exists() {
            return Err(BagError::Exists { path: path(folder) });
        }
        std::fs::create_dir_all(folder).map_err(|source| BagError::Io {
            path: path(folder),
            source,
        })?;
        let stem = folder
            .file_name()
            .map_or_else(|| "bag".to_string(), |n| n.to_string_lossy().into_owned());
        let file_name = format!("{stem}_0.mcap");
        let file_path = folder.join(&file_name);
        let file = File::create(&file_path).map_err(|source| BagError::Io {
            path: path(&file_path),
            source,
        })?;
        let out = mcap::WriteOptions::new()
            .profile("ros2")
            .library(concat!("pv3d player-ros2 ", env!("CARGO_PKG_VERSION")))
            .create(BufWriter::new(file))
            .map_err(|source| BagError::Mcap {
                path: path(&file_path),
                source,
            })?;
        Ok(BagWriter {
            folder: folder.to_path_buf(),
            file_name,
            out,
            schemas: HashMap::new(),
            channels: HashMap::new(),
            connections: HashMap::new(),
            names: names
                .iter()
                .map(|r| ((r.host().to_string(), r.port()), namespace(r)))
                .collect(),
            stats: BagStats::default(),
            sequence: 0,
            first_ns: None,
            last_ns: 0,
        })
    }

    /// Adds one record: a connection's declaration names its robot; a message from the server
    /// becomes its ROS 2 messages.
    pub fn write(&mut self, record: &Record) -> Result<(), BagError> {
        match &record.event {
            Event::Connection { host, port } => {
                let ns = self
                    .names
                    .get(&(host.clone(), *port))
                    .cloned()
                    .unwrap_or_else(|| namespace(&RobotId::new(host.clone(), *port)));
                self.connections
                    .insert(record.connection, Converter::new(ns));
            }
            Event::Message {
                direction: Direction::ServerToClient,
                header,
                body,
            } => {
                let Some(converter) = self.connections.get_mut(&record.connection) else {
                    return Ok(());
                };
                let Ok(message) = Message::decode(*header, body.clone()) else {
                    self.stats.undecodable += 1;
                    return Ok(());
                };
                let converted = converter.convert(&message);
                if converted.is_empty() {
                    self.stats.unmapped += 1;
                }
                for c in converted {
                    self.put(record.time_ns, c)?;
                }
            }
            _ => {}
        }
        Ok(())
    }

    fn put(&mut self, time_ns: u64, c: Converted) -> Result<(), BagError> {
        let file = self.folder.join(&self.file_name).display().to_string();
        let failed = |source| BagError::Mcap {
            path: file.clone(),
            source,
        };
        let type_name = c.message.type_name();
        let channel = match self.channels.get(&c.topic) {
            Some(&(id, _)) => id,
            None => {
                let schema = match self.schemas.get(type_name) {
                    Some(&id) => id,
                    None => {
                        let text = c.message.schema();
                        let id = self
                            .out
                            .add_schema(type_name, "ros2msg", text.as_bytes())
                            .map_err(failed)?;
                        self.schemas.insert(type_name, id);
                        id
                    }
                };
                let metadata =
                    BTreeMap::from([("offered_qos_profiles".to_string(), qos(&c.topic))]);
                let id = self
                    .out
                    .add_channel(schema, &c.topic, "cdr", &metadata)
                    .map_err(failed)?;
                self.channels.insert(c.topic.clone(), (id, type_name));
                id
            }
        };
        let header = MessageHeader {
            channel_id: channel,
            sequence: self.sequence,
            log_time: time_ns,
            publish_time: time_ns,
        };
        self.sequence = self.sequence.wrapping_add(1);
        let cdr = c.message.cdr()?;
        self.out
            .write_to_known_channel(&header, &cdr)
            .map_err(failed)?;
        self.first_ns = Some(self.first_ns.map_or(time_ns, |f| f.min(time_ns)));
        self.last_ns = self.last_ns.max(time_ns);
        *self.stats.topics.entry(c.topic).or_default() += 1;
        Ok(())
    }

    /// Ends the MCAP file and writes `metadata.yaml`.
    pub fn finish(mut self) -> Result<BagStats, BagError> {
        let file = self.folder.join(&self.file_name).display().to_string();
        self.out
            .finish()
            .map_err(|source| BagError::Mcap { path: file, source })?;
        let metadata = self.metadata();
        let path = self.folder.join("metadata.yaml");
        let written = File::create(&path).and_then(|mut f| f.write_all(metadata.as_bytes()));
        written.map_err(|source| BagError::Io {
            path: path.display().to_string(),
            source,
        })?;
        Ok(self.stats)
    }

    /// rosbag2's `metadata.yaml` (version 5: read by every rosbag2 from Humble on).
    fn metadata(&self) -> String {
        let start = self.first_ns.unwrap_or(0);
        let duration = self.last_ns.saturating_sub(start);
        let count: u64 = self.stats.topics.values().sum();
        let mut topics = String::new();
        for (topic, n) in &self.stats.topics {
            let type_name = self.channels.get(topic).map_or("", |&(_, t)| t);
            let qos = qos(topic).replace('"', "\\\"").replace('\n', "\\n");
            topics.push_str(&format!(
                "    - topic_metadata:\n        name: {topic}\n        type: {type_name}\n        serialization_format: cdr\n        offered_qos_profiles: \"{qos}\"\n      message_count: {n}\n"
            ));
        }
        if topics.is_empty() {
            topics = "    []\n".into();
        }
        format!(
            "rosbag2_bagfile_information:\n  version: 5\n  storage_identifier: mcap\n  duration:\n    nanoseconds: {duration}\n  starting_time:\n    nanoseconds_since_epoch: {start}\n  message_count: {count}\n  topics_with_message_count:\n{topics}  compression_format: \"\"\n  compression_mode: \"\"\n  relative_file_paths:\n    - {file}\n  files:\n    - path: {file}\n      starting_time:\n        nanoseconds_since_epoch: {start}\n      duration:\n        nanoseconds: {duration}\n      message_count: {count}\n",
            file = self.file_name
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_bag_is_written_anew_never_over_another() {
        let dir = tempfile::tempdir().unwrap();
        let error = BagWriter::create(dir.path(), &[]).err().unwrap();
        assert!(error.to_string().contains("exists"), "{error}");
        let bag = BagWriter::create(&dir.path().join("empty"), &[]).unwrap();
        let stats = bag.finish().unwrap();
        assert!(stats.topics.is_empty());
        let metadata = std::fs::read_to_string(dir.path().join("empty/metadata.yaml")).unwrap();
        assert!(metadata.contains("message_count: 0\n") && metadata.contains("- empty_0.mcap"));
    }

    #[test]
    fn sensor_data_is_best_effort_and_the_rest_reliable() {
        assert!(qos("/r0/scan").contains("reliability: 2"));
        assert!(qos("/r0/scan_1").contains("reliability: 2"));
        assert!(qos("/r0/odom").contains("reliability: 1"));
        assert!(qos("/tf_static").contains("durability: 1"));
        assert!(qos("/r0/range_1").contains("reliability: 2"));
        assert!(qos("/r0/camera_info").contains("reliability: 2"));
        assert!(qos("/map").contains("durability: 1") && qos("/map").contains("reliability: 1"));
    }
}
