; A sliding-tile puzzle played by pushing: tiles stand in the cells of a
; 2 x 2 grid with one cell empty; a tile may only slide into the adjacent
; empty cell. The planar disk cannot lift tiles (there is no pick), it
; pushes them from outside the grid.
(define (domain slide-puzzle)
  (:requirements :strips :typing)
  (:types tile cell)
  (:predicates (at ?t - tile ?c - cell)
               (empty ?c - cell)
               (adj ?a - cell ?b - cell))
  (:action slide
    :parameters (?t - tile ?from - cell ?to - cell)
    :precondition (and (at ?t ?from) (empty ?to) (adj ?from ?to))
    :effect (and (not (at ?t ?from)) (at ?t ?to)
                 (not (empty ?to)) (empty ?from))))
