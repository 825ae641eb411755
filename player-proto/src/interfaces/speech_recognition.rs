//! The `speech_recognition` interface (code 50): text a recogniser heard.

use crate::wire::PlayerString;

xdr_struct! {
    /// `player_speech_recognition_data_t`.
    pub struct SpeechRecognitionData {
        pub text: PlayerString,
    }
}

interface_messages! {
    /// Messages of the `speech_recognition` interface.
    pub enum SpeechRecognition for SPEECH_RECOGNITION {
        Data 1 as DATA_STRING => Text(SpeechRecognitionData),
    }
}
