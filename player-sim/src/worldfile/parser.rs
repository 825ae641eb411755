//! The syntax tree of a world or config file: properties (`name value`), blocks
//! (`kind ( … )`), `define name base ( … )` and `include "file"`.

use super::WorldFileError;
use super::lexer::{Located, Token};

/// A property value.
#[derive(Debug, Clone, PartialEq)]
pub enum Value {
    Number(f64),
    Str(String),
    Word(String),
    List(Vec<Value>),
}

impl Value {
    pub fn as_f64(&self) -> Option<f64> {
        match self {
            Value::Number(n) => Some(*n),
            _ => None,
        }
    }

    pub fn as_str(&self) -> Option<&str> {
        match self {
            Value::Str(s) | Value::Word(s) => Some(s),
            _ => None,
        }
    }

    /// The numbers of a list value.
    pub fn numbers(&self) -> Option<Vec<f64>> {
        match self {
            Value::List(items) => items.iter().map(Value::as_f64).collect(),
            Value::Number(n) => Some(vec![*n]),
            _ => None,
        }
    }
}

/// Where something was written.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Pos {
    pub file: String,
    pub line: usize,
    pub col: usize,
}

impl std::fmt::Display for Pos {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}:{}:{}", self.file, self.line, self.col)
    }
}

#[derive(Debug, Clone, PartialEq)]
pub struct Property {
    pub name: String,
    pub value: Value,
    pub pos: Pos,
}

/// `kind ( properties and child blocks )`.
#[derive(Debug, Clone, PartialEq)]
pub struct Block {
    pub kind: String,
    pub properties: Vec<Property>,
    pub children: Vec<Block>,
    pub pos: Pos,
}

impl Block {
    /// The last value given for a property (later ones override earlier ones, as in Stage).
    pub fn get(&self, name: &str) -> Option<&Property> {
        self.properties.iter().rev().find(|p| p.name == name)
    }
}

/// A top-level item.
#[derive(Debug, Clone, PartialEq)]
pub enum Item {
    Include {
        path: String,
        pos: Pos,
    },
    Define {
        name: String,
        base: String,
        body: Block,
    },
    Block(Block),
    Property(Property),
}

/// Blocks inside blocks, at most: a robot's sensors inside it are two or three deep. Each
/// level is a call here and in everything that walks the tree later, so a file of nothing but
/// `a(a(a(…` would otherwise end the program with a stack overflow.
const MAX_NESTING: usize = 64;

struct Parser<'a> {
    tokens: &'a [Located],
    at: usize,
    file: &'a str,
    /// Blocks open around the one being read.
    nesting: usize,
}

impl Parser<'_> {
    fn pos(&self) -> Pos {
        let (line, col) = match self.tokens.get(self.at).or(self.tokens.last()) {
            Some(t) => (t.line, t.col),
            None => (1, 1),
        };
        Pos {
            file: self.file.to_string(),
            line,
            col,
        }
    }

    fn error(&self, message: impl Into<String>) -> WorldFileError {
        let pos = self.pos();
        WorldFileError::at(&pos.file, pos.line, pos.col, message)
    }

    fn peek(&self) -> Option<&Token> {
        self.tokens.get(self.at).map(|t| &t.token)
    }

    fn next(&mut self) -> Option<&Token> {
        let t = self.tokens.get(self.at).map(|t| &t.token);
        self.at += 1;
        t
    }

    fn value(&mut self) -> Result<Value, WorldFileError> {
        let pos_error =
            self.error("expected a value: a number, a \"string\", a word or a [ list ]");
        Ok(match self.next() {
            Some(Token::Number(n)) => Value::Number(*n),
            Some(Token::Str(s)) => Value::Str(s.clone()),
            Some(Token::Word(w)) => Value::Word(w.clone()),
            Some(Token::ListOpen) => {
                let mut items = Vec::new();
                loop {
                    match self.peek() {
                        Some(Token::ListClose) => {
                            self.next();
                            break;
                        }
                        None => return Err(self.error("list not closed with ]")),
                        _ => items.push(self.value()?),
                    }
                }
                Value::List(items)
            }
            _ => return Err(pos_error),
        })
    }

    /// The inside of `( … )`, after the `(`.
    fn body(&mut self, kind: String, pos: Pos) -> Result<Block, WorldFileError> {
        if self.nesting >= MAX_NESTING {
            return Err(WorldFileError::at(
                &pos.file,
                pos.line,
                pos.col,
                format!("block {kind:?} is nested more than {MAX_NESTING} blocks deep"),
            ));
        }
        self.nesting += 1;
        let block = self.block_items(kind, pos);
        self.nesting -= 1;
        block
    }

    fn block_items(&mut self, kind: String, pos: Pos) -> Result<Block, WorldFileError> {
        let mut block = Block {
            kind,
            properties: Vec::new(),
            children: Vec::new(),
            pos,
        };
        loop {
            let pos = self.pos();
            match self.next().cloned() {
                Some(Token::Close) => return Ok(block),
                None => {
                    return Err(WorldFileError::at(
                        &block.pos.file,
                        block.pos.line,
                        block.pos.col,
                        format!("block {:?} is not closed with )", block.kind),
                    ));
                }
                Some(Token::Word(name)) => {
                    if self.peek() == Some(&Token::Open) {
                        self.next();
                        block.children.push(self.body(name, pos)?);
                    } else {
                        let value = self.value()?;
                        block.properties.push(Property { name, value, pos });
                    }
                }
                Some(other) => {
                    self.at -= 1;
                    return Err(self.error(format!(
                        "expected a property name or a block, found {other:?}"
                    )));
                }
            }
        }
    }

    fn items(&mut self) -> Result<Vec<Item>, WorldFileError> {
        let mut items = Vec::new();
        while self.peek().is_some() {
            let pos = self.pos();
            let Some(Token::Word(word)) = self.next().cloned() else {
                self.at -= 1;
                return Err(self.error("expected a property name, a block, `define` or `include`"));
            };
            match word.as_str() {
                "include" => match self.next().cloned() {
                    Some(Token::Str(path)) => items.push(Item::Include { path, pos }),
                    _ => {
                        self.at -= 1;
                        return Err(self.error("include needs a \"file name\""));
                    }
                },
                "define" => {
                    let (Some(Token::Word(name)), Some(Token::Word(base))) =
                        (self.next().cloned(), self.next().cloned())
                    else {
                        return Err(WorldFileError::at(
                            self.file,
                            pos.line,
                            pos.col,
                            "define needs a name and a base model: define name base ( … )",
                        ));
                    };
                    if self.next() != Some(&Token::Open) {
                        self.at -= 1;
                        return Err(self.error(format!("expected ( after define {name} {base}")));
                    }
                    let body = self.body(base.clone(), pos)?;
                    items.push(Item::Define { name, base, body });
                }
                _ if self.peek() == Some(&Token::Open) => {
                    self.next();
                    items.push(Item::Block(self.body(word, pos)?));
                }
                _ => {
                    let value = self.value()?;
                    items.push(Item::Property(Property {
                        name: word,
                        value,
                        pos,
                    }));
                }
            }
        }
        Ok(items)
    }
}

/// Parses a file's tokens into its items.
pub fn parse(tokens: &[Located], file: &str) -> Result<Vec<Item>, WorldFileError> {
    Parser {
        tokens,
        at: 0,
        file,
        nesting: 0,
    }
    .items()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::worldfile::lexer::tokenize;

    fn items(text: &str) -> Result<Vec<Item>, WorldFileError> {
        parse(&tokenize(text, "t.world")?, "t.world")
    }

    #[test]
    fn defines_blocks_properties_and_includes() {
        let parsed = items(
            "include \"robots.inc\"\ninterval_sim 100\ndefine laser ranger ( sensor( range [ 0 8 ] samples 181 ) color \"blue\" )\nlaser( name \"l\" pose [ 1 2 0 90 ] )\n",
        )
        .unwrap();
        assert!(matches!(&parsed[0], Item::Include { path, .. } if path == "robots.inc"));
        assert!(
            matches!(&parsed[1], Item::Property(p) if p.name == "interval_sim" && p.value == Value::Number(100.0))
        );
        let Item::Define { name, base, body } = &parsed[2] else {
            panic!()
        };
        assert_eq!((name.as_str(), base.as_str()), ("laser", "ranger"));
        assert_eq!(body.children[0].kind, "sensor");
        assert_eq!(
            body.children[0].get("samples").unwrap().value,
            Value::Number(181.0)
        );
        let Item::Block(b) = &parsed[3] else { panic!() };
        assert_eq!(
            b.get("pose").unwrap().value.numbers().unwrap(),
            [1.0, 2.0, 0.0, 90.0]
        );
        assert_eq!((b.pos.line, b.pos.col), (4, 1));
    }

    #[test]
    fn syntax_errors_say_where_and_what() {
        assert_eq!(
            items("model\n( size [ 1 2 ]\n").unwrap_err().to_string(),
            "t.world:1:1: block \"model\" is not closed with )"
        );
        assert_eq!(
            items("pose [ 1 2\n").unwrap_err().to_string(),
            "t.world:1:10: list not closed with ]"
        );
        assert_eq!(
            items("define r ( x 1 )").unwrap_err().to_string(),
            "t.world:1:1: define needs a name and a base model: define name base ( … )"
        );
        assert!(
            items("[ 1 ]")
                .unwrap_err()
                .to_string()
                .starts_with("t.world:1:1: expected a property name")
        );
    }

    /// Every level of nesting is a call here and in whatever walks the blocks later: a file
    /// of `a(a(a(…` is refused where it passes the limit, not a stack overflow.
    #[test]
    fn blocks_nested_past_the_limit_are_refused_where_the_limit_is_passed() {
        let deep = |levels: usize| "a(\n".repeat(levels) + &")".repeat(levels);
        assert!(items(&deep(MAX_NESTING)).is_ok());
        assert_eq!(
            items(&deep(100_000)).unwrap_err().to_string(),
            format!(
                "t.world:{}:1: block \"a\" is nested more than {MAX_NESTING} blocks deep",
                MAX_NESTING + 1
            )
        );
    }
}
