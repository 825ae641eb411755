//! A whole message: header plus typed body, and the registry that maps interface codes to
//! their message sets.

use std::fmt;

use bytes::{Buf, BufMut, Bytes, BytesMut};

use crate::interfaces;
use crate::view_disagreement::ViewDisagreement;
use crate::wire::xdr::{XdrError, XdrFault};
use crate::wire::{DevAddr, HEADER_LEN, Header, Interface, MessageClass, MsgType};

/// Declares [`Body`] with one variant per implemented interface, and its dispatch.
macro_rules! bodies {
    ($( $(#[$meta:meta])* $variant:ident => $code:ident, $ty:ty; )*) => {
        /// A message body, typed when the interface and subtype are known.
        #[derive(Debug, Clone, PartialEq)]
        #[cfg_attr(any(test, feature = "proptest"), derive(proptest_derive::Arbitrary))]
        #[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
        pub enum Body {
            /// No body (`size` 0): "get" requests, empty ACKs and NACKs, SYNCH, data requests.
            Empty,
            /// A capability or property request, valid on every interface.
            Universal(interfaces::universal::Universal),
            $( $(#[$meta])* $variant($ty), )*
            /// A body this crate does not decode (unknown interface or subtype), kept verbatim
            /// so it re-encodes byte for byte.
            Unknown(
                #[cfg_attr(any(test, feature = "proptest"), proptest(strategy = "crate::message::arbitrary_bytes()"))]
                #[cfg_attr(feature = "serde", serde(with = "crate::wire::serde_bytes"))]
                Bytes,
            ),
        }

        impl Body {
            /// Decodes a non-empty body into its message: the interface's own decoder builds
            /// it (see [`MessageSet::decode_message`]), universal requests on any interface.
            fn decode_message(header: Header, body: Bytes) -> Result<Message, DecodeError> {
                let interf = header.addr.interf;
                if header.msg_type.class() == MessageClass::Request && header.subtype >= 247 {
                    return interfaces::universal::Universal::decode_message(header, body);
                }
                $(
                    if interf == Interface::$code {
                        return <$ty>::decode_message(header, body);
                    }
                )*
                Ok(Message::unknown(header, body))
            }

            /// Checks that viewing `body` in place agrees with decoding it: the same value
            /// (compared by its encoding, so NaNs compare) or the same error. For the tests and
            /// the `message_body` fuzz target (through [`crate::fuzz_input`]).
            #[doc(hidden)]
            pub fn view_agrees(header: &Header, body: &Bytes) -> Result<(), ViewDisagreement> {
                let interf = header.addr.interf;
                if header.msg_type.class() == MessageClass::Request && header.subtype >= 247 {
                    return interfaces::universal::Universal::view_agrees(header, body);
                }
                $(
                    if interf == Interface::$code {
                        return <$ty>::view_agrees(header, body);
                    }
                )*
                Ok(())
            }

            /// The interface this typed body belongs to (`None` for empty, universal and
            /// unknown bodies, which fit any).
            pub fn interface(&self) -> Option<Interface> {
                match self {
                    $( Body::$variant(_) => Some(Interface::$code), )*
                    _ => None,
                }
            }

            /// Class and subtype of a typed body.
            pub fn kind(&self) -> Option<(MessageClass, u8)> {
                match self {
                    Body::Universal(v) => Some((v.class(), v.subtype())),
                    $( Body::$variant(v) => Some((v.class(), v.subtype())), )*
                    Body::Empty | Body::Unknown(_) => None,
                }
            }

            pub fn encode<B: BufMut>(&self, out: &mut B) {
                match self {
                    Body::Empty => {}
                    Body::Universal(v) => v.encode(out),
                    $( Body::$variant(v) => v.encode(out), )*
                    Body::Unknown(raw) => out.put_slice(raw),
                }
            }

            pub fn encoded_len(&self) -> usize {
                match self {
                    Body::Empty => 0,
                    Body::Universal(v) => v.encoded_len(),
                    $( Body::$variant(v) => v.encoded_len(), )*
                    Body::Unknown(raw) => raw.len(),
                }
            }
        }

        impl interfaces::kind::MessageKind {
            /// Every message an interface's table defines, in table order (none for an
            /// interface this crate does not decode).
            pub fn all_of(interf: Interface) -> &'static [interfaces::kind::MessageKind] {
                use interfaces::kind::InterfaceMessages;
                $(
                    if interf == Interface::$code {
                        return <$ty>::KINDS;
                    }
                )*
                &[]
            }
        }

        $(
            impl From<$ty> for Body {
                fn from(v: $ty) -> Body {
                    Body::$variant(v)
                }
            }
        )*
    };
}

bodies! {
    Player => PLAYER, interfaces::player::Player;
    Laser => LASER, interfaces::laser::Laser;
    Sonar => SONAR, interfaces::sonar::Sonar;
    Position2d => POSITION2D, interfaces::position2d::Position2d;
    Fiducial => FIDUCIAL, interfaces::fiducial::Fiducial;
    Camera => CAMERA, interfaces::camera::Camera;
    Ranger => RANGER, interfaces::ranger::Ranger;
    Simulation => SIMULATION, interfaces::simulation::Simulation;
    Blobfinder => BLOBFINDER, interfaces::blobfinder::Blobfinder;
    Map => MAP, interfaces::map::Map;
    Graphics2d => GRAPHICS2D, interfaces::graphics2d::Graphics2d;
    Graphics3d => GRAPHICS3D, interfaces::graphics3d::Graphics3d;
    Speech => SPEECH, interfaces::speech::Speech;
    Bumper => BUMPER, interfaces::bumper::Bumper;
    Power => POWER, interfaces::power::Power;
    Gripper => GRIPPER, interfaces::gripper::Gripper;
    Localize => LOCALIZE, interfaces::localize::Localize;
    Planner => PLANNER, interfaces::planner::Planner;
    Ptz => PTZ, interfaces::ptz::Ptz;
    Ir => IR, interfaces::ir::Ir;
    Pointcloud3d => POINTCLOUD3D, interfaces::pointcloud3d::Pointcloud3d;
    SpeechRecognition => SPEECH_RECOGNITION, interfaces::speech_recognition::SpeechRecognition;
    // Left out of `Body`'s generated strategy (one more arm overflows the 2 MiB stack of a
    // debug test thread); `interfaces::log` has its own round-trip property.
    #[cfg_attr(any(test, feature = "proptest"), proptest(skip))]
    Log => LOG, interfaces::log::Log;
}

impl From<interfaces::universal::Universal> for Body {
    fn from(v: interfaces::universal::Universal) -> Body {
        Body::Universal(v)
    }
}

#[cfg(any(test, feature = "proptest"))]
pub(crate) fn arbitrary_bytes() -> impl proptest::strategy::Strategy<Value = Bytes> {
    use proptest::strategy::Strategy;
    proptest::collection::vec(proptest::arbitrary::any::<u8>(), 0..64).prop_map(Bytes::from)
}

/// A body that could not be decoded: names the interface, type, subtype, field and the byte
/// offset within the body where decoding failed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{}", self.describe())]
pub struct DecodeError {
    pub header: Header,
    /// Offset within the body where the failing item starts.
    pub offset: usize,
    pub fault: XdrFault,
    /// `"LaserScan.ranges"`, when known.
    pub field: Option<String>,
}

impl DecodeError {
    #[cold]
    pub(crate) fn from_xdr(header: Header, body: &[u8], err: XdrError<'_>) -> DecodeError {
        let offset = body.len().saturating_sub(err.input.len());
        DecodeError {
            header,
            offset,
            fault: err.fault,
            field: err
                .field
                .map(|f| format!("{}.{}", err.within.unwrap_or("?"), f)),
        }
    }

    fn describe(&self) -> String {
        let h = &self.header;
        let field = match &self.field {
            Some(f) => format!(" in {f}"),
            None => String::new(),
        };
        format!(
            "cannot decode {} {} subtype {} from {}: {} at body byte {} of {}{}",
            h.addr.interf, h.msg_type, h.subtype, h.addr, self.fault, self.offset, h.size, field
        )
    }
}

impl fmt::Display for XdrFault {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            XdrFault::Truncated => f.write_str("body ends early"),
            XdrFault::LengthAboveCount { count, length } => {
                write!(f, "array length {length} exceeds its count {count}")
            }
            XdrFault::LengthBeyondBody { length, remaining } => write!(
                f,
                "array length {length} cannot fit in the {remaining} bytes left"
            ),
            XdrFault::LengthAboveMax { length, max } => {
                write!(f, "array length {length} exceeds its maximum {max}")
            }
            XdrFault::Malformed => f.write_str("malformed value"),
        }
    }
}

/// The last `n` bytes of `wire`, which the typed body left unread: logged, kept verbatim.
#[cold]
fn trailing_bytes(header: &Header, mut wire: Bytes, n: usize) -> Bytes {
    tracing::debug!(%header, trailing = n, "body has trailing bytes; kept verbatim");
    wire.advance(wire.len() - n);
    wire
}

/// A Player message: header and body.
#[derive(Debug, Clone, PartialEq)]
pub struct Message {
    /// The header as received, or as it will be sent; `size` is recomputed on encoding.
    pub header: Header,
    pub body: Body,
    /// Bytes after the end of a typed body but within the header's `size`, kept verbatim and
    /// re-encoded after the body.
    ///
    /// Player's own decoder skips such bytes silently, so a server may send them (a driver
    /// built against a newer interface definition that appended fields, or padding). Dropping
    /// them would make a recorder or relay (`playerdump`, the replaying server) change the
    /// stream; refusing them would lose data a Player client accepts. Keeping them makes every
    /// accepted message re-encode byte for byte, and a non-empty `trailing` reports them.
    /// Empty for messages built here.
    pub trailing: Bytes,
}

impl Message {
    /// A message with an explicit subtype, e.g. a bodiless "get" request.
    pub fn new(addr: DevAddr, msg_type: MsgType, subtype: u8, body: Body) -> Message {
        let size = u32::try_from(body.encoded_len()).expect("body above 4 GiB");
        Message {
            header: Header {
                addr,
                msg_type,
                subtype,
                timestamp: 0.0,
                seq: 0,
                size,
            },
            body,
            trailing: Bytes::new(),
        }
    }

    /// A message whose subtype follows from its typed body.
    ///
    /// # Panics
    /// If `body` is empty or unknown (use [`Message::new`] for those).
    pub fn typed(addr: DevAddr, msg_type: MsgType, body: impl Into<Body>) -> Message {
        let body = body.into();
        let (_, subtype) = body
            .kind()
            .expect("Message::typed needs a typed body; use Message::new");
        Message::new(addr, msg_type, subtype, body)
    }

    /// Sets the timestamp.
    pub fn at(mut self, timestamp: f64) -> Message {
        self.header.timestamp = timestamp;
        self
    }

    /// Decodes a framed body. Never panics; an undecodable body is an error naming the
    /// interface, subtype, field and offset. Unknown interfaces and subtypes decode to
    /// [`Body::Unknown`].
    pub fn decode(header: Header, body: Bytes) -> Result<Message, DecodeError> {
        if body.is_empty() {
            return Ok(Message {
                header,
                body: Body::Empty,
                trailing: Bytes::new(),
            });
        }
        Body::decode_message(header, body)
    }

    /// A message whose body this crate does not decode, kept verbatim.
    pub(crate) fn unknown(header: Header, body: Bytes) -> Message {
        Message {
            header,
            body: Body::Unknown(body),
            trailing: Bytes::new(),
        }
    }

    /// The `trailing` of a message whose typed body left `n` bytes of `wire` unread.
    #[inline]
    pub(crate) fn trailing_of(header: &Header, wire: Bytes, n: usize) -> Bytes {
        match n {
            0 => Bytes::new(),
            n => trailing_bytes(header, wire, n),
        }
    }

    /// Length of the body as it travels: the typed body and any trailing bytes.
    pub fn body_len(&self) -> usize {
        self.body.encoded_len() + self.trailing.len()
    }

    /// Encoded length, header included.
    pub fn encoded_len(&self) -> usize {
        HEADER_LEN + self.body_len()
    }

    /// Appends header, body and trailing bytes; the header's `size` is their length.
    pub fn encode<B: BufMut>(&self, out: &mut B) {
        let mut header = self.header;
        header.size = u32::try_from(self.body_len()).expect("body above 4 GiB");
        header.encode(out);
        self.body.encode(out);
        out.put_slice(&self.trailing);
    }

    /// The wire bytes in one buffer.
    pub fn to_bytes(&self) -> Bytes {
        let mut out = BytesMut::with_capacity(self.encoded_len());
        self.encode(&mut out);
        out.freeze()
    }
}

/// The typed messages of one interface.
pub trait MessageSet: Sized {
    /// Decodes the body of a message of this interface, class and subtype from `header`,
    /// into the whole message: a body the interface defines no structure for is kept as
    /// [`Body::Unknown`](crate::message::Body::Unknown), bytes left after the structure as
    /// the message's `trailing`.
    ///
    /// It returns the finished [`Message`] rather than the body because a laser scan is
    /// decoded every few microseconds: built here, in the place it is returned to, the value
    /// is not moved again through a body, an optional result and a message (a 181-beam scan
    /// spent more time in those moves than in converting its ranges).
    fn decode_message(header: Header, body: Bytes) -> Result<Message, DecodeError>;

    /// Whether viewing `body` in place agrees with decoding it (see [`crate::wire::xdr_view`]);
    /// for the tests and the fuzz target.
    #[doc(hidden)]
    fn view_agrees(header: &Header, body: &Bytes) -> Result<(), ViewDisagreement>;

    /// The class this body belongs to.
    fn class(&self) -> MessageClass;

    /// The subtype number it is sent with.
    fn subtype(&self) -> u8;

    fn encode<B: BufMut>(&self, out: &mut B);

    fn encoded_len(&self) -> usize;
}
