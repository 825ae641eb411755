//! How a server delivers one connection's messages: the data mode (PUSH or PULL) and the
//! replace rules of its outgoing queue (protocol document §4.5 and §4.7).
//!
//! Both ends need the same ideas — the client to ask for them and replay them after a
//! reconnect, the server to apply them — so they are defined once here, with the only
//! translation to and from the request bodies that carry them.

use crate::interfaces::player::{
    AddReplaceRuleReq, DATAMODE_PULL, DATAMODE_PUSH, DataModeReq, REPLACE_RULE_ACCEPT,
    REPLACE_RULE_IGNORE, REPLACE_RULE_REPLACE,
};
use crate::wire::{Header, Interface, MsgType};

/// How a replace-rule filter says "any value" on the wire.
const ANY: i32 = -1;

/// PUSH (data as soon as it is published) or PULL (data on request).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum DataMode {
    /// The server default.
    #[default]
    Push,
    Pull,
}

impl DataMode {
    /// The request body that asks for this mode.
    pub fn to_request(self) -> DataModeReq {
        DataModeReq {
            mode: match self {
                DataMode::Push => DATAMODE_PUSH,
                DataMode::Pull => DATAMODE_PULL,
            },
        }
    }

    /// The mode a request asks for; `None` for a code Player does not know (it ignores such a
    /// request, yet ACKs it).
    pub fn from_request(req: &DataModeReq) -> Option<DataMode> {
        match req.mode {
            DATAMODE_PUSH => Some(DataMode::Push),
            DATAMODE_PULL => Some(DataMode::Pull),
            _ => None,
        }
    }
}

/// What the server does with a message a rule matches.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum ReplaceAction {
    /// Queue it normally (subject to the queue's length limit). Also what happens to a message
    /// no rule matches.
    #[default]
    Accept,
    /// Replace the newest queued message of the same address, type and subtype.
    Replace,
    /// Drop it silently.
    Ignore,
}

impl ReplaceAction {
    pub fn code(self) -> i32 {
        match self {
            ReplaceAction::Accept => REPLACE_RULE_ACCEPT,
            ReplaceAction::Replace => REPLACE_RULE_REPLACE,
            ReplaceAction::Ignore => REPLACE_RULE_IGNORE,
        }
    }

    /// Player queues normally under a rule whose action code it does not know.
    pub fn from_code(code: i32) -> ReplaceAction {
        match code {
            REPLACE_RULE_REPLACE => ReplaceAction::Replace,
            REPLACE_RULE_IGNORE => ReplaceAction::Ignore,
            _ => ReplaceAction::Accept,
        }
    }
}

/// One replace rule. A filter left `None` matches anything (it travels as -1).
///
/// Beware a rule without a message type filter: it also matches ACK and NACK, and with
/// [`ReplaceAction::Ignore`] it would swallow every reply.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ReplaceRule {
    pub interf: Option<Interface>,
    pub index: Option<u16>,
    pub msg_type: Option<MsgType>,
    pub subtype: Option<u8>,
    pub action: ReplaceAction,
}

impl ReplaceRule {
    /// A rule for DATA messages of every device.
    pub fn data(action: ReplaceAction) -> ReplaceRule {
        ReplaceRule {
            interf: None,
            index: None,
            msg_type: Some(MsgType::Data),
            subtype: None,
            action,
        }
    }

    /// The viewer default: newest DATA replaces older queued DATA of the same device and
    /// subtype.
    pub fn newest_data() -> ReplaceRule {
        ReplaceRule::data(ReplaceAction::Replace)
    }

    /// A rule for DATA messages of one device (`interf:index`).
    pub fn device_data(interf: Interface, index: u16, action: ReplaceAction) -> ReplaceRule {
        ReplaceRule {
            interf: Some(interf),
            index: Some(index),
            ..ReplaceRule::data(action)
        }
    }

    /// Narrows the rule to one message subtype.
    pub fn with_subtype(self, subtype: u8) -> ReplaceRule {
        ReplaceRule {
            subtype: Some(subtype),
            ..self
        }
    }

    /// Does the rule apply to a message with this header? Host and robot never matter.
    pub fn matches(&self, h: &Header) -> bool {
        fn fits<T: PartialEq>(filter: Option<T>, value: T) -> bool {
            filter.is_none_or(|f| f == value)
        }
        fits(self.interf, h.addr.interf)
            && fits(self.index, h.addr.index)
            && fits(self.msg_type, h.msg_type)
            && fits(self.subtype, h.subtype)
    }

    fn same_filters(&self, other: &ReplaceRule) -> bool {
        (self.interf, self.index, self.msg_type, self.subtype)
            == (other.interf, other.index, other.msg_type, other.subtype)
    }

    /// The request body as it travels.
    pub fn to_request(&self) -> AddReplaceRuleReq {
        AddReplaceRuleReq {
            interf: self.interf.map_or(ANY, |i| i32::from(i.0)),
            index: self.index.map_or(ANY, i32::from),
            msg_type: self.msg_type.map_or(ANY, |t| i32::from(t.code())),
            subtype: self.subtype.map_or(ANY, i32::from),
            replace: self.action.code(),
        }
    }

    /// The rule a request asks for. `None` when a filter holds a value no message can have
    /// (a negative other than -1, an interface beyond 16 bits, an unknown message type): such
    /// a rule never matches, so keeping it or not makes no difference to the queue.
    pub fn from_request(req: &AddReplaceRuleReq) -> Option<ReplaceRule> {
        fn filter<T>(value: i32, convert: impl FnOnce(i32) -> Option<T>) -> Option<Option<T>> {
            if value == ANY {
                Some(None)
            } else {
                convert(value).map(Some)
            }
        }
        Some(ReplaceRule {
            interf: filter(req.interf, |v| u16::try_from(v).ok().map(Interface))?,
            index: filter(req.index, |v| u16::try_from(v).ok())?,
            msg_type: filter(req.msg_type, |v| {
                u8::try_from(v).ok().and_then(MsgType::from_code)
            })?,
            subtype: filter(req.subtype, |v| u8::try_from(v).ok())?,
            action: ReplaceAction::from_code(req.replace),
        })
    }
}

/// A connection's replace rules, in the order the server tries them; the first match decides.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct ReplaceRules(Vec<ReplaceRule>);

impl ReplaceRules {
    /// Adds a rule as the server does: one with the same filters as an existing rule only
    /// changes that rule's action (keeping its place); anything else goes last.
    pub fn add(&mut self, rule: ReplaceRule) {
        match self.0.iter_mut().find(|r| r.same_filters(&rule)) {
            Some(existing) => existing.action = rule.action,
            None => self.0.push(rule),
        }
    }

    /// What happens to a message with this header.
    pub fn action_for(&self, h: &Header) -> ReplaceAction {
        self.0
            .iter()
            .find(|r| r.matches(h))
            .map(|r| r.action)
            .unwrap_or_default()
    }

    pub fn as_slice(&self) -> &[ReplaceRule] {
        &self.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::message::{Body, Message};
    use crate::wire::DevAddr;

    fn header(msg_type: MsgType) -> Header {
        Message::new(
            DevAddr::local(Interface::LASER, 0),
            msg_type,
            1,
            Body::Empty,
        )
        .header
    }

    fn fields(req: AddReplaceRuleReq) -> [i32; 5] {
        [
            req.interf,
            req.index,
            req.msg_type,
            req.subtype,
            req.replace,
        ]
    }

    #[test]
    fn wildcards_travel_as_minus_one_and_come_back() {
        let newest = ReplaceRule::newest_data();
        assert_eq!(fields(newest.to_request()), [-1, -1, 1, -1, 1]);
        let laser =
            ReplaceRule::device_data(Interface::LASER, 2, ReplaceAction::Ignore).with_subtype(1);
        assert_eq!(fields(laser.to_request()), [6, 2, 1, 1, 2]);
        for rule in [newest, laser] {
            assert_eq!(ReplaceRule::from_request(&rule.to_request()), Some(rule));
        }
    }

    #[test]
    fn filters_no_message_can_match_make_no_rule() {
        let base = ReplaceRule::newest_data().to_request();
        for bad in [
            AddReplaceRuleReq {
                interf: 70_000,
                ..base
            },
            AddReplaceRuleReq { index: -2, ..base },
            AddReplaceRuleReq {
                msg_type: 7,
                ..base
            },
            AddReplaceRuleReq {
                subtype: 256,
                ..base
            },
        ] {
            assert_eq!(ReplaceRule::from_request(&bad), None, "{bad:?}");
        }
        let odd_action = AddReplaceRuleReq { replace: 9, ..base };
        assert_eq!(
            ReplaceRule::from_request(&odd_action).map(|r| r.action),
            Some(ReplaceAction::Accept)
        );
    }

    #[test]
    fn data_modes_round_trip_and_unknown_codes_are_none() {
        for mode in [DataMode::Push, DataMode::Pull] {
            assert_eq!(DataMode::from_request(&mode.to_request()), Some(mode));
        }
        assert_eq!(DataMode::from_request(&DataModeReq { mode: 9 }), None);
    }

    #[test]
    fn same_filters_change_the_action_in_place_and_the_first_match_decides() {
        let mut rules = ReplaceRules::default();
        rules.add(ReplaceRule::newest_data());
        let laser = ReplaceRule::device_data(Interface::LASER, 0, ReplaceAction::Ignore);
        rules.add(laser);
        let data = header(MsgType::Data);
        assert_eq!(rules.action_for(&data), ReplaceAction::Replace);
        rules.add(ReplaceRule::data(ReplaceAction::Accept));
        assert_eq!(
            rules.as_slice(),
            [ReplaceRule::data(ReplaceAction::Accept), laser]
        );
        assert_eq!(rules.action_for(&data), ReplaceAction::Accept);
        let reply = header(MsgType::Ack);
        assert_eq!(rules.action_for(&reply), ReplaceAction::Accept);
    }
}
