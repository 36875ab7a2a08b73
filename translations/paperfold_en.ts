<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en" sourcelanguage="en">
<!-- English is the source language: this file holds only its plural forms (Qt's
     numerus messages, "(s)" in the source), which the editor loads when no other
     language is chosen. Regenerate its entries with
     lupdate -pluralonly -locations none -no-obsolete ui render -ts translations/paperfold_en.ts
     (README.md; it drops this comment). -->
<context>
    <name>UndoCommands</name>
    <message numerus="yes">
        <source>Push (%n break(s) or hinge(s))</source>
        <translation>
            <numerusform>Push (%n break or hinge)</numerusform>
            <numerusform>Push (%n breaks or hinges)</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Grab (%n break(s) or hinge(s))</source>
        <translation>
            <numerusform>Grab (%n break or hinge)</numerusform>
            <numerusform>Grab (%n breaks or hinges)</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Pin %n vertex(es)</source>
        <translation>
            <numerusform>Pin %n vertex</numerusform>
            <numerusform>Pin %n vertices</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Unpin %n vertex(es)</source>
        <translation>
            <numerusform>Unpin %n vertex</numerusform>
            <numerusform>Unpin %n vertices</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Fold (%n break(s) or hinge(s))</source>
        <translation>
            <numerusform>Fold (%n break or hinge)</numerusform>
            <numerusform>Fold (%n breaks or hinges)</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>pf::SolverPanel</name>
    <message numerus="yes">
        <source>%n per second</source>
        <translation>
            <numerusform>%n per second</numerusform>
            <numerusform>%n per second</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>How many of this computer&apos;s %n cores step the sheet. The sheet moves the same, to the last bit, on any number; by default one core is left to draw the view.</source>
        <translation>
            <numerusform>How many of this computer&apos;s %n core steps the sheet. The sheet moves the same, to the last bit, on any number.</numerusform>
            <numerusform>How many of this computer&apos;s %n cores step the sheet. The sheet moves the same, to the last bit, on any number; by default one core is left to draw the view.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>pf::StatusReadout</name>
    <message numerus="yes">
        <source>%n break(s)</source>
        <translation>
            <numerusform>%n break</numerusform>
            <numerusform>%n breaks</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n hinge(s)</source>
        <translation>
            <numerusform>%n hinge</numerusform>
            <numerusform>%n hinges</numerusform>
        </translation>
    </message>
</context>
</TS>
