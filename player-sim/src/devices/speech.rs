//! The speech devices' messages: each sentence heard becomes one speech-recognition data
//! message; a speech command is said.

use player_proto::interfaces::speech::Speech;
use player_proto::interfaces::speech_recognition::{SpeechRecognition, SpeechRecognitionData};
use player_proto::message::{Body, Message};
use player_proto::wire::PlayerString;

use super::data_of;
use crate::sim::Simulation;
use crate::speech::{SpeechInput, SpeechOutput};

pub(super) fn heard(sim: &Simulation, input: &SpeechInput) -> Vec<(u8, Body)> {
    input
        .heard(sim.time)
        .into_iter()
        .map(|text| {
            let data = SpeechRecognitionData {
                text: PlayerString::new(&text),
            };
            data_of(SpeechRecognition::DATA_STRING, data)
        })
        .collect()
}

pub(super) fn say(output: &SpeechOutput, command: &Message) {
    if let Body::Speech(Speech::Say(said)) = &command.body {
        output.say(&said.string.as_str());
    }
}
