//! The `speech` interface (code 12): text to say.

use crate::wire::PlayerString;

xdr_struct! {
    /// `player_speech_cmd_t`.
    pub struct SpeechCmd {
        pub string: PlayerString,
    }
}

interface_messages! {
    /// Messages of the `speech` interface.
    pub enum Speech for SPEECH {
        Command 1 as CMD_SAY => Say(SpeechCmd),
    }
}
