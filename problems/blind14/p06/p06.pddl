; blind14 p06: a cube, a can and a bar stand on the riser's work area;
; clear it (into the two bins on the table), hand free at the end.
(define (problem p06)
  (:domain xarm-clear)
  (:objects cube can bar - item
            work bin-l bin-r - area)
  (:init (in cube work) (in can work) (in bar work) (handfree))
  (:goal (and (handfree)
              (forall (?o - item) (not (in ?o work))))))
