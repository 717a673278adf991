pub fn exercise() -> Result<crate::model::Exercise, super::SheetError> { Ok(crate::model::Exercise { id: "13".into(), statement: crate::text::Text::same(""), parts: vec![] }) }
