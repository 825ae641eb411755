//! Speech through Player: sentences a `speech_recognition` device hears go to the same
//! grammar as the command line, and every reply is said through a `speech` device, when the
//! servers offer them. The devices are found among the servers' devices as they appear.

use std::sync::Arc;
use std::time::{Duration, Instant};

use framework::config::DeviceRef;
use framework::device::{DeviceAccess, LastTaken};
use player_proto::interfaces::speech::{Speech, SpeechCmd};
use player_proto::interfaces::speech_recognition::SpeechRecognition;
use player_proto::message::Body;
use player_proto::wire::{DevAddr, Interface, PlayerString};

use super::Viewer;

/// How often the servers' device lists are looked through for speech devices: often enough
/// to notice one soon, rarely enough to cost nothing with hundreds of servers.
const SCAN_INTERVAL: Duration = Duration::from_secs(1);

/// The speech devices linked so far.
#[derive(Default)]
pub(super) struct SpeechLinks {
    /// Recognisers, with the sentence taken last from each.
    ears: Vec<(DevAddr, Arc<dyn DeviceAccess>, LastTaken)>,
    voices: Vec<(DevAddr, Arc<dyn DeviceAccess>)>,
    last_scan: Option<Instant>,
}

impl Viewer {
    /// Links speech devices that appeared, then carries out what they heard since last time.
    pub(super) fn follow_speech(&mut self, now: Instant) {
        let due = self
            .speech
            .last_scan
            .is_none_or(|at| now.saturating_duration_since(at) >= SCAN_INTERVAL);
        if due {
            self.speech.last_scan = Some(now);
            self.link_speech_devices();
        }
        let mut heard = Vec::new();
        for (_, device, last) in &mut self.speech.ears {
            let kind = SpeechRecognition::DATA_STRING.kind();
            if let Some(sample) = last.newest(Some(device.as_ref()), kind)
                && let Body::SpeechRecognition(SpeechRecognition::Text(data)) = &sample.message.body
            {
                heard.push(data.text.as_str().to_string());
            }
        }
        for sentence in heard {
            tracing::info!("heard {sentence:?}");
            // The outcome is said and shown by `command` itself.
            let _ = self.command(&sentence);
        }
    }

    /// Says `text` through every speech device (none: nothing happens).
    pub(super) fn say(&self, text: &str) {
        for (_, voice) in &self.speech.voices {
            voice.command(Body::Speech(Speech::Say(SpeechCmd {
                string: PlayerString::new(text),
            })));
        }
    }

    fn link_speech_devices(&mut self) {
        let Some(robots) = self.robots.clone() else {
            return;
        };
        for (host, port, client) in robots.clients() {
            for info in client.devices() {
                let addr = info.addr;
                let is_ear = addr.interf == Interface::SPEECH_RECOGNITION;
                if !is_ear && addr.interf != Interface::SPEECH {
                    continue;
                }
                let known = self.speech.ears.iter().any(|(a, ..)| *a == addr)
                    || self.speech.voices.iter().any(|(a, _)| *a == addr);
                if known {
                    continue;
                }
                let device = DeviceRef {
                    host: host.to_string(),
                    port,
                    addr,
                    driver: info.driver.clone(),
                };
                let Some(access) = robots.device(&device) else {
                    continue;
                };
                tracing::info!("speech: using {device}");
                if is_ear {
                    self.speech.ears.push((addr, access, LastTaken::default()));
                } else {
                    self.speech.voices.push((addr, access));
                }
            }
        }
    }
}
