!> The *DATABASE_MATSUM file 'matsum': per-part energies and momenta at the request's DT, in
!> LS-DYNA's ASCII layout so that its readers parse it: a header ending in the part legend
!> ('{BEGIN LEGEND}' ... '{END LEGEND}'), then per output time a line 'time = t' and per part
!> four lines
!>    mat.#= <part id>  inten= IE  kinen= KE  eroded_ie= 0  eroded_ke= 0
!>                      x-mom= px  y-mom= py  z-mom= pz
!>                      x-rbv= vx  y-rbv= vy  z-rbv= vz
!>                      hgeng= HG  +mass= added mass  eroded_he= 0
!> The layout and labels follow LS-DYNA's matsum as its post-processors read it (LS-DYNA
!> Keyword User's Manual Vol. I, *DATABASE_MATSUM; the field labels are those a public matsum
!> parser matches: 'mat.#=', 'inten=', 'kinen=', 'eroded_ie=', 'eroded_ke=', 'x-mom=', ...,
!> 'x-rbv=', ..., 'hgeng=', '+mass=', 'eroded_he=' after 'time ='). 'mat.#' is the part id
!> (LS-DYNA's old "material" naming). Numbers are written with 10 significant digits
!> (es18.10e3, as glstat) instead of LS-DYNA's 5, so the sums can be checked to round-off.
!> rbv is the part's rigid-body velocity, momentum / (mass + added mass). eroded_ie and
!> eroded_ke: the part's eroded elements' internal energy and its share of the kinetic
!> energy of the nodes no living element holds (dx_energy_sums%eroded_energies; parts of
!> inten and kinen, as in glstat); eroded_he is 0 (an eroded element's hourglass energy
!> stays in hgeng). The header lists each part's mass (rho V0).
!> The numbers come from dx_energy_sums%part_energies (model%psum).
module dx_matsum
   use dx_kinds, only: wp
   use dx_error, only: error_t, set_error, EXIT_IO
   use dx_model, only: model_t
   implicit none
   private
   public :: matsum_header, matsum_record, part_masses

   character(*), parameter :: NUM = 'es18.10e3'

contains

   !> The header: title, the part masses and the legend (part id and title).
   function matsum_header(model) result(text)
      type(model_t), intent(in) :: model
      character(:), allocatable :: text
      character(200) :: line
      character(:), allocatable :: title
      real(wp), allocatable :: pm(:)
      integer :: p
      character, parameter :: nl = new_line('a')
      title = ''
      if (allocated(model%title)) title = trim(model%title)
      text = ' Summary of material energies for '//title//nl// &
             ' dynx matsum (LS-DYNA matsum layout; mat.# = part id; 10 significant digits)'//nl
      pm = part_masses(model)
      if (allocated(pm)) then
         do p = 1, size(model%parts)
            write(line, '(" part ",i10,"   mass= ",'//NUM//')') model%parts(p)%label, pm(p)
            text = text//trim(line)//nl
         end do
      end if
      text = text//' {BEGIN LEGEND}'//nl//'  Entity #        Title'//nl
      do p = 1, size(model%parts)
         title = ''
         if (allocated(model%parts(p)%title)) title = trim(model%parts(p)%title)
         write(line, '(i10,5x,a)') model%parts(p)%label, title
         text = text//trim(line)//nl
      end do
      text = text//' {END LEGEND}'//nl
   end function matsum_header

   !> Each part's mass, rho V0 summed over its elements (not allocated when the element
   !> volumes are not at hand).
   function part_masses(model) result(pm)
      type(model_t), intent(in) :: model
      real(wp), allocatable :: pm(:)
      integer :: b
      if (.not. allocated(model%blocks)) return
      do b = 1, size(model%blocks)
         if (.not. allocated(model%blocks(b)%vol0)) return
      end do
      allocate(pm(size(model%parts)))
      pm = 0.0_wp
      do b = 1, size(model%blocks)
         associate (ip => model%blocks(b)%ipart)
            pm(ip) = pm(ip) + model%mats(model%parts(ip)%imat)%m%ro*sum(model%blocks(b)%vol0)
         end associate
      end do
   end function part_masses

   !> One output time: 'time =' and four lines per part (an empty text when the sums are
   !> not formed).
   subroutine matsum_record(model, text, error)
      type(model_t), intent(in) :: model
      character(:), allocatable, intent(out) :: text
      type(error_t), allocatable, intent(out) :: error
      character(200) :: line
      character(256) :: msg
      character, parameter :: nl = new_line('a')
      real(wp) :: mt, rbv(3)
      integer :: p, ios
      text = ''
      if (.not. allocated(model%psum%ie)) return
      ios = 0
      fmt: associate (ps => model%psum)
         write(line, '(" time = ",'//NUM//')', iostat=ios, iomsg=msg) model%time
         if (ios /= 0) exit fmt
         text = nl//trim(line)//nl
         do p = 1, size(ps%ie)
            mt = ps%mass(p) + ps%added(p)
            rbv = 0.0_wp
            if (mt > 0.0_wp) rbv = ps%mom(:, p)/mt
            write(line, '(" mat.#=",i10,8x,"inten=",'//NUM//',5x,"kinen=",'//NUM// &
                  ',5x,"eroded_ie=",'//NUM//',5x,"eroded_ke=",'//NUM//')', iostat=ios, &
                  iomsg=msg) model%parts(p)%label, ps%ie(p), ps%ke(p), ps%eie(p), ps%eke(p)
            if (ios /= 0) exit fmt
            text = text//trim(line)//nl
            write(line, '(25x,"x-mom=",'//NUM//',5x,"y-mom=",'//NUM//',5x,"z-mom=",'//NUM// &
                  ')', iostat=ios, iomsg=msg) ps%mom(:, p)
            if (ios /= 0) exit fmt
            text = text//trim(line)//nl
            write(line, '(25x,"x-rbv=",'//NUM//',5x,"y-rbv=",'//NUM//',5x,"z-rbv=",'//NUM// &
                  ')', iostat=ios, iomsg=msg) rbv
            if (ios /= 0) exit fmt
            text = text//trim(line)//nl
            write(line, '(25x,"hgeng=",'//NUM//',5x,"+mass=",'//NUM//',5x,"eroded_he=",'// &
                  NUM//')', iostat=ios, iomsg=msg) ps%hge(p), ps%added(p), 0.0_wp
            if (ios /= 0) exit fmt
            text = text//trim(line)//nl
         end do
      end associate fmt
      if (ios /= 0) call set_error(error, 'cannot format a matsum record: '//trim(msg), EXIT_IO)
   end subroutine matsum_record
end module dx_matsum
